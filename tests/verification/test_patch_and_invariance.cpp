// SPDX-License-Identifier: MIT
// Patch tests (rigid motion, uniform extension on distorted meshes), invariance under
// translation and mirroring, and independence of the secant iteration from its start.
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/mesh_transform.hpp"
#include "support/approx.hpp"
#include "verification/verification_support.hpp"

#include <gtest/gtest.h>

namespace formflow {
namespace {

/// Nodal interpolant of `field` (exact for the linear fields used here).
template <class Field> VectorX interpolate(const mesh::Mesh<2>& mesh, Field field) {
  VectorX u(2 * mesh.n_nodes());
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    u.segment<2>(2 * node) = field(Point<2>(mesh.nodes.col(node)));
  return u;
}

TEST(PatchTest, RigidBodyMotionDissipatesNothing) {
  for (int order : {1, 2}) {
    const mesh::Mesh<2> channel = mesh::make_channel_mesh(mesh::ChannelGeometry{}, 2.5, order);
    const mesh::Mesh<2> box = mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), 5, 5,
                                                  order, {mesh::Distortion::Random, 0.2, 4});
    for (const mesh::Mesh<2>* grid : {&channel, &box}) {
      const assembly::FormingProblem<2> problem(*grid, app::problem_settings(io::Case{}));
      // Rotation by ω = 0.3 about the origin plus a translation.
      const VectorX rigid = interpolate(
          *grid, [](const Point<2>& x) { return Point<2>(0.7 - 0.3 * x.y(), -0.2 + 0.3 * x.x()); });
      const post::PowerTerms power =
          post::compute_powers(problem, rigid, problem.contact_state(rigid));
      EXPECT_LT(power.plastic_dissipation, 1e-20);
      EXPECT_LT(power.viscous_form, 1e-20);
      EXPECT_LT(power.volumetric_penalty, 1e-20);
      // The check can fail: a shear of the same size dissipates.
      const VectorX shear =
          interpolate(*grid, [](const Point<2>& x) { return Point<2>(0.3 * x.y(), 0.0); });
      EXPECT_GT(
          post::compute_powers(problem, shear, problem.contact_state(shear)).plastic_dissipation,
          1e-2);
    }
  }
}

TEST(PatchTest, UniformExtensionIsReproducedExactlyOnDistortedMeshes) {
  for (fem::ElementKind element : {fem::ElementKind::Q1, fem::ElementKind::Q2})
    for (mesh::Distortion distortion : {mesh::Distortion::Smooth, mesh::Distortion::Random})
      for (bool nonlinear : {false, true}) {
        io::Case case_ = testing::manufactured_case(element, 0.25, distortion, nonlinear);
        case_.manufactured = physics::ManufacturedSolution::Extension;
        for (int points : {1, 2, 3}) { // every volumetric rule: ε̇_V(u) = 0 at any point
          case_.volumetric_points = points;
          const app::Simulation simulation = app::simulate(case_);
          ASSERT_TRUE(simulation.results.converged());
          // Round-off only: the field lies in the isoparametric space.
          EXPECT_LT(simulation.errors->v_norm, 1e-9) << fem::element_name(element) << " " << points;
          EXPECT_LT(simulation.errors->l2, 1e-10);
        }
      }
}

TEST(Invariance, TranslationChangesNothing) {
  const io::Case case_ = testing::coarse_benchmark();
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(case_.mesh.geometry, case_.mesh.size, 2);
  const testing::Solved original = testing::solve_on(mesh, case_);
  const testing::Solved moved =
      testing::solve_on(mesh::translated(mesh, Point<2>(37.5, -12.25)), case_);
  ASSERT_TRUE(original.results.converged() && moved.results.converged());
  EXPECT_EQ(original.results.iterations, moved.results.iterations);
  // Round-off in the coordinates (|x| ≈ 40) reaches the solution amplified by the conditioning.
  EXPECT_TRUE(testing::approx(moved.results.pressure.ram_reaction,
                              original.results.pressure.ram_reaction, 1e-8));
  EXPECT_LT((moved.velocity - original.velocity).norm(), 1e-7 * original.velocity.norm());
}

TEST(Invariance, MirroringTheMeshMirrorsTheSolution) {
  const io::Case case_ = testing::coarse_benchmark();
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(case_.mesh.geometry, case_.mesh.size, 2);
  const testing::Solved original = testing::solve_on(mesh, case_);
  const testing::Solved image = testing::solve_on(mesh::mirrored(mesh, 1), case_);
  ASSERT_TRUE(original.results.converged() && image.results.converged());
  EXPECT_TRUE(testing::approx(image.results.pressure.ram_reaction,
                              original.results.pressure.ram_reaction, 1e-10));
  VectorX reflected = original.velocity;
  for (Index node = 0; node < mesh.n_nodes(); ++node) reflected[2 * node + 1] *= -1.0;
  EXPECT_LT((image.velocity - reflected).norm(), 1e-8 * original.velocity.norm());
}

TEST(SecantStarts, ReachTheSameAnswer) {
  io::Case case_ = testing::coarse_benchmark();
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(case_.mesh.geometry, case_.mesh.size, 2);
  const testing::Solved reference = testing::solve_on(mesh, case_);
  ASSERT_TRUE(reference.results.converged());

  std::vector<testing::Solved> others;
  for (Real rate : {1e-2, 1e2}) { // starting viscosity 100× larger / smaller
    io::Case varied = case_;
    varied.solver.initial_rate = rate;
    others.push_back(testing::solve_on(mesh, varied));
  }
  // A scaled and perturbed constant-viscosity solution (zero iterations = u⁰ itself).
  io::Case first_only = case_;
  first_only.solver.max_iterations = 0;
  VectorX start = 1.7 * testing::solve_on(mesh, first_only).velocity;
  for (Index k = 0; k < start.size(); ++k) start[k] += 0.3 * std::sin(1.3 * k);
  others.push_back(testing::solve_on(mesh, case_, &start));

  for (const testing::Solved& other : others) {
    ASSERT_TRUE(other.results.converged());
    // δ = 1e-9 per step and a contraction well below 1: agreement to ~1e-7.
    EXPECT_LT((other.velocity - reference.velocity).norm(), 1e-6 * reference.velocity.norm());
    EXPECT_TRUE(testing::approx(other.results.pressure.ram_reaction,
                                reference.results.pressure.ram_reaction, 1e-6));
  }
}

} // namespace
} // namespace formflow
