// SPDX-License-Identifier: MIT
// The exit section's velocities and flux balance of a prescribed flow: a uniform axial
// velocity crosses the entry (height 10) and the exit (height 5) of the benchmark
// channel, so the exit carries half the entry's flux (a quarter in axisymmetry, where
// the sections are discs of radius 10 and 5, per radian r²/2).
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/simplex_split.hpp"
#include "formflow/post/exit_flow.hpp"

#include <gtest/gtest.h>

namespace formflow::post {
namespace {

/// u = (speed, 0) at every node, plus `slope` · (x-independent) y in u_x (a shear).
VectorX axial_flow(const mesh::Mesh<2>& mesh, Real speed, Real slope) {
  VectorX u = VectorX::Zero(2 * mesh.n_nodes());
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    u[fem::dof_of<2>(node, 0)] = speed + slope * mesh.nodes(1, node);
  return u;
}

ExitFlow flow_of(const mesh::Mesh<2>& mesh, physics::Symmetry symmetry, Real slope = 0.0) {
  assembly::ProblemSettings settings;
  settings.symmetry = symmetry;
  const assembly::FormingProblem<2> problem(mesh, settings);
  return exit_flow(problem, axial_flow(mesh, 1.5, slope));
}

std::vector<mesh::Mesh<2>> channel_meshes() {
  const mesh::Mesh<2> quadrilaterals = mesh::make_channel_mesh(mesh::ChannelGeometry{}, 1.0, 2);
  return {quadrilaterals, mesh::split_into_triangles(quadrilaterals, true)};
}

TEST(ExitFlow, UniformFlowCarriesTheSectionsRatio) {
  for (const mesh::Mesh<2>& mesh : channel_meshes()) {
    const ExitFlow plane = flow_of(mesh, physics::Symmetry::Plane);
    ASSERT_TRUE(plane.present);
    EXPECT_NEAR(plane.area, 5.0, 1e-12);
    EXPECT_NEAR(plane.entry_flux, 15.0, 1e-12);
    EXPECT_NEAR(plane.exit_flux, 7.5, 1e-12);
    EXPECT_NEAR(plane.flux_balance, -0.5, 1e-13);
    EXPECT_NEAR(plane.velocity_min, 1.5, 1e-15);
    EXPECT_NEAR(plane.velocity_max, 1.5, 1e-15);
    EXPECT_NEAR(plane.velocity_mean, 1.5, 1e-13);
    EXPECT_NEAR(plane.nonuniformity.value(), 0.0, 1e-13);
    const ExitFlow round = flow_of(mesh, physics::Symmetry::Axisymmetric);
    EXPECT_NEAR(round.area, 12.5, 1e-12); // ∫₀⁵ r dr
    EXPECT_NEAR(round.entry_flux, 1.5 * 50.0, 1e-11);
    EXPECT_NEAR(round.flux_balance, -0.75, 1e-13);
  }
}

TEST(ExitFlow, ShearSpreadsTheExitVelocity) {
  // u_x = 1.5 + 0.1 y over the exit y ∈ [0, 5]: min 1.5, max 2, plane mean 1.75,
  // axisymmetric (r-weighted) mean 1.5 + 0.1 · (∫ r² dr / ∫ r dr) = 1.5 + 0.1 · 10/3.
  for (const mesh::Mesh<2>& mesh : channel_meshes()) {
    const ExitFlow plane = flow_of(mesh, physics::Symmetry::Plane, 0.1);
    EXPECT_NEAR(plane.velocity_min, 1.5, 1e-14);
    EXPECT_NEAR(plane.velocity_max, 2.0, 1e-14);
    EXPECT_NEAR(plane.velocity_mean, 1.75, 1e-13);
    EXPECT_NEAR(plane.nonuniformity.value(), 0.5 / 1.75, 1e-13);
    const ExitFlow round = flow_of(mesh, physics::Symmetry::Axisymmetric, 0.1);
    EXPECT_NEAR(round.velocity_mean, 1.5 + 1.0 / 3.0, 1e-13);
    // The profile: each exit node once (Q2/P2 on h = 1: 11 along y ∈ [0, 5]), ascending.
    ASSERT_EQ(plane.profile.size(), 11u);
    for (std::size_t k = 0; k < plane.profile.size(); ++k) {
      EXPECT_NEAR(plane.profile[k][0], 0.5 * static_cast<Real>(k), 1e-14);
      EXPECT_NEAR(plane.profile[k][1], 1.5 + 0.1 * plane.profile[k][0], 1e-14);
    }
  }
}

TEST(ExitFlow, NoMetalOutHasNoNonuniformity) {
  // The prescribed values alone (what a run whose first solve failed holds): the rear
  // pushes in, nothing moves at the exit. Its spread has no mean to divide by: none, not
  // the NaN that summary.json refused as an internal error (exit 1 instead of 3).
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(mesh::ChannelGeometry{}, 1.0, 2);
  VectorX u = VectorX::Zero(2 * mesh.n_nodes());
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    if (mesh.nodes(0, node) == 0.0) u[fem::dof_of<2>(node, 0)] = 1.0; // the rear, x = 0
  const assembly::FormingProblem<2> problem(mesh, assembly::ProblemSettings{});
  const ExitFlow flow = exit_flow(problem, u);
  ASSERT_TRUE(flow.present);
  EXPECT_EQ(flow.velocity_mean, 0.0);
  EXPECT_FALSE(flow.nonuniformity.has_value());
  // No exit node moves: the exit flux is a sum of exact zeros, the balance 0/F − 1.
  EXPECT_EQ(flow.flux_balance, -1.0);
}

TEST(ExitFlow, AMeshWithoutAnExitHasNone) {
  mesh::Mesh<2> mesh = mesh::make_channel_mesh(mesh::ChannelGeometry{}, 1.0, 1);
  for (mesh::BoundaryFacet& facet : mesh.facets)
    if (facet.label == mesh::BoundaryLabel::Front) facet.label = mesh::BoundaryLabel::FreeExit;
  EXPECT_FALSE(flow_of(mesh, physics::Symmetry::Plane).present);
}

} // namespace
} // namespace formflow::post
