// SPDX-License-Identifier: MIT
// FormingProblem's geometry cache (fem/values_cache.hpp) against values mapped
// afresh: on a curved wedge-die mesh, plane and axisymmetric, face and nodal
// contact normals, every cell at both rules and every Γ3 point agree exactly.
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"

#include <gtest/gtest.h>

namespace formflow::testing {
namespace {

using namespace assembly;
using Nodes = fem::CellValues<2>::Gradients;

mesh::Mesh<2> wedge_mesh(int order) {
  mesh::ChannelGeometry geometry{1.0, 1.0, 0.6, 1.0};
  geometry.die = mesh::DieShape::Arc; // curved die face: curved Q2 cells
  geometry.die_radius = 1.0;
  geometry.land_length = 0.25;
  return mesh::make_die_channel_mesh(geometry, 0.125, order);
}

struct CacheCase {
  int order;
  physics::Symmetry symmetry;
  ContactNormals normals;
};

class GeometryCache : public ::testing::TestWithParam<CacheCase> {};

TEST_P(GeometryCache, CellValuesEqualFreshlyMappedOnes) {
  const CacheCase c = GetParam();
  const mesh::Mesh<2> m = wedge_mesh(c.order);
  ProblemSettings settings;
  settings.symmetry = c.symmetry;
  settings.contact.normals = c.normals;
  const FormingProblem<2> problem(m, settings);
  fem::CellValues<2> fresh_full(c.order, problem.full_rule()),
      fresh_volumetric(c.order, problem.volumetric_rule());
  fem::CellValues<2> full(c.order, problem.full_rule()),
      volumetric(c.order, problem.volumetric_rule());
  Nodes coordinates, unused;
  for (Index cell = m.n_cells() - 1; cell >= 0; --cell) {
    problem.gather(cell, nullptr, coordinates, unused);
    problem.reinit(fresh_full, coordinates);
    problem.reinit(fresh_volumetric, coordinates);
    problem.load_cell(cell, full, &volumetric);
    for (int q = 0; q < full.n_points(); ++q) {
      ASSERT_EQ(full.JxW(q), fresh_full.JxW(q)) << "cell " << cell;
      ASSERT_EQ(full.gradients(q), fresh_full.gradients(q)) << "cell " << cell;
      ASSERT_EQ(full.point(q), fresh_full.point(q)) << "cell " << cell;
    }
    for (int q = 0; q < volumetric.n_points(); ++q) {
      ASSERT_EQ(volumetric.JxW(q), fresh_volumetric.JxW(q)) << "cell " << cell;
      ASSERT_EQ(volumetric.gradients(q), fresh_volumetric.gradients(q)) << "cell " << cell;
    }
  }
  EXPECT_GT(problem.geometry_cache_bytes(), 0u);
}

TEST_P(GeometryCache, ContactPointsEqualFreshlyMappedFaces) {
  const CacheCase c = GetParam();
  const mesh::Mesh<2> m = wedge_mesh(c.order);
  ProblemSettings settings;
  settings.symmetry = c.symmetry;
  settings.contact.normals = c.normals;
  const FormingProblem<2> problem(m, settings);
  // A velocity with a normal and a tangential part on every face.
  VectorX u(problem.n_dofs());
  for (Index node = 0; node < m.n_nodes(); ++node)
    u.segment<2>(2 * node) = Point<2>(1.0 + 0.3 * m.nodes(1, node), -0.4 * m.nodes(0, node));
  const std::vector<ContactPoint<2>> state = problem.contact_state(u);
  ASSERT_EQ(static_cast<Index>(state.size()), problem.n_contact_points());
  ASSERT_GT(state.size(), 0u);
  fem::FacetValues<2> fresh(c.order, problem.facet_rule());
  Nodes coordinates, velocities;
  const int n_q = problem.facet_rule().size();
  for (std::size_t k = 0; k < state.size(); k += n_q) {
    const mesh::BoundaryFacet& facet = m.facets[state[k].facet];
    problem.gather(facet.cell, &u, coordinates, velocities);
    problem.reinit(fresh, coordinates, facet.local_face);
    for (int q = 0; q < n_q; ++q) {
      const ContactPoint<2>& point = state[k + q];
      EXPECT_EQ(point.position, fresh.point(q));
      EXPECT_EQ(point.weight, fresh.JxW(q));
      const Point<2> velocity = velocities * fresh.shape(q);
      if (c.normals == ContactNormals::Faces) {
        EXPECT_EQ(point.normal, fresh.normal(q));
        EXPECT_EQ(point.normal_velocity, velocity.dot(fresh.normal(q)));
      } else { // nodal normals: unit, and the velocity split along them
        EXPECT_NEAR(point.normal.norm(), 1.0, 1e-14);
        EXPECT_NEAR(point.normal_velocity, velocity.dot(point.normal), 1e-14);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Assembly, GeometryCache,
    ::testing::Values(CacheCase{2, physics::Symmetry::Plane, ContactNormals::Faces},
                      CacheCase{2, physics::Symmetry::Axisymmetric, ContactNormals::Faces},
                      CacheCase{2, physics::Symmetry::Axisymmetric, ContactNormals::Nodes},
                      CacheCase{1, physics::Symmetry::Plane, ContactNormals::Nodes}));

} // namespace
} // namespace formflow::testing
