// SPDX-License-Identifier: MIT
// Issue 15: the rectangle quarter model (and the round billet through the square
// die) runs with Newton and its ram reaction equals
// the total discrete power to the iteration tolerance; surfaces with edges and
// corners (the square die's L-shaped face, the container's corner line), face and
// nodal normals, regularised and exact friction.
#include "formflow/app/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

namespace formflow::testing {
namespace {

using physics::FrictionRegularization;

/// δ of the runs. At a fixed point K(u)u = F, so uᵀK(u)u = u⁰·reaction exactly
/// (the reaction is the driven rows' force); at an iterate u* + e the two differ by
/// u*ᵀ K e, relatively ‖e‖/‖u‖ up to the ratio of K's norms on the two vectors. A
/// Newton iterate stopped at a relative change δ is converging quadratically, so
/// its own error is below that change: |R − P|/R ≤ 10 δ leaves a factor 10 for the
/// norm ratio, while a missing or wrong term (a corner penalty, a 2-vector slip)
/// leaves a discrepancy of the order of that term's power, far above 1e-7.
constexpr Real tolerance = 1e-8;
constexpr Real power_gap = 10 * tolerance;

struct RectangleCase {
  fem::ElementKind element;
  mesh::DieShape die;
  FrictionRegularization regularization;
  assembly::ContactNormals normals;
};

/// {L_c = 1, H_in = 1, H_out = 0.5, L_e = 1} × half widths 1 → 0.5 at h = 0.25:
/// a square bar reduced to a quarter of its area (80 cubes with the square die).
io::Case rectangle_case(const RectangleCase& rectangle) {
  io::Case case_;
  case_.solver.load_error = solvers::LoadErrorMethod::None; // not checked here; costs runs
  case_.mesh.geometry = mesh::ChannelGeometry{1.0, 1.0, 0.5, 1.0};
  case_.mesh.geometry.die = rectangle.die;
  case_.mesh.geometry.die_angle = 45.0;
  case_.mesh.size = 0.25;
  case_.mesh.dimension = 3;
  case_.mesh.solid.section = mesh::ChannelSection::Rectangle;
  case_.mesh.solid.entry_half_width = 1.0;
  case_.mesh.solid.exit_half_width = 0.5;
  case_.element = rectangle.element;
  case_.volumetric_points = rectangle.element == fem::ElementKind::Q1 ? 1 : 2;
  case_.friction.mu = 0.1;
  case_.friction.radius = 0.3;
  case_.friction.regularization = rectangle.regularization;
  case_.contact.normals = rectangle.normals;
  case_.solver.method = solvers::NonlinearMethod::Newton;
  case_.solver.tolerance = tolerance;
  return case_;
}

class RectangleBar : public ::testing::TestWithParam<RectangleCase> {};

TEST_P(RectangleBar, NewtonConvergesAndTheReactionEqualsTheTotalPower) {
  const app::Simulation run = app::simulate(rectangle_case(GetParam()));
  ASSERT_EQ(run.dimension(), 3);
  const post::Results& results = run.results;
  ASSERT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  const Real reaction = results.pressure.ram_reaction;
  EXPECT_GT(reaction, 0.0);
  EXPECT_LT(std::abs(reaction - results.pressure.total_power), power_gap * reaction)
      << reaction << " vs " << results.pressure.total_power;
  // Friction does work on the walls: the bar slides along them.
  EXPECT_GT(results.power.friction, 0.0);
  // Ideal work is a lower bound of any kinematically admissible field's power
  // (SPEC §6): p ≥ σ₀ ln(A₀/A_f) with σ₀ = √3 k, A₀/A_f = 4 here.
  EXPECT_GT(reaction, std::sqrt(3.0) * std::log(4.0));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RectangleBar,
    ::testing::Values(
        RectangleCase{fem::ElementKind::Q1, mesh::DieShape::Square,
                      FrictionRegularization::Regularized, assembly::ContactNormals::Faces},
        RectangleCase{fem::ElementKind::Q1, mesh::DieShape::Square, FrictionRegularization::None,
                      assembly::ContactNormals::Nodes},
        RectangleCase{fem::ElementKind::Q2, mesh::DieShape::Square,
                      FrictionRegularization::Regularized, assembly::ContactNormals::Nodes},
        RectangleCase{fem::ElementKind::Q1, mesh::DieShape::Wedge,
                      FrictionRegularization::Regularized, assembly::ContactNormals::Nodes},
        RectangleCase{fem::ElementKind::Q2, mesh::DieShape::Wedge,
                      FrictionRegularization::Regularized, assembly::ContactNormals::Faces}),
    [](const auto& info) {
      const RectangleCase& c = info.param;
      return std::string(c.element == fem::ElementKind::Q1 ? "Q1" : "Q2") +
             (c.die == mesh::DieShape::Square ? "Square" : "Wedge") +
             (c.regularization == FrictionRegularization::None ? "Exact" : "Regularized") +
             (c.normals == assembly::ContactNormals::Faces ? "FaceNormals" : "NodalNormals");
    });

/// A round billet through the square die (mesh/round_square_die_mesh.hpp):
/// {L_c = 1, R = 1, H_out = 0.5, L_e = 1}, exit 0.5 × 0.5 (W_out = 0.5) at h = 0.25:
/// the flat die face is the quarter disk minus the exit square, meeting the
/// cylinder and the product's sides at right angles (64 hexahedra); μ = 0.1,
/// nonlocal radius 0.3, δ = 1e-8 as the bar's.
io::Case round_square_case(fem::ElementKind element, assembly::ContactNormals normals,
                           FrictionRegularization regularization) {
  RectangleCase base{element, mesh::DieShape::Square, regularization, normals};
  io::Case case_ = rectangle_case(base);
  case_.mesh.solid.section = mesh::ChannelSection::Round;
  return case_;
}

class RoundBilletSquareDie
    : public ::testing::TestWithParam<
          std::tuple<fem::ElementKind, assembly::ContactNormals, FrictionRegularization>> {};

TEST_P(RoundBilletSquareDie, NewtonConvergesAndTheReactionEqualsTheTotalPower) {
  const auto [element, normals, regularization] = GetParam();
  const app::Simulation run = app::simulate(round_square_case(element, normals, regularization));
  ASSERT_EQ(run.dimension(), 3);
  const post::Results& results = run.results;
  ASSERT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  const Real reaction = results.pressure.ram_reaction;
  EXPECT_GT(reaction, 0.0);
  EXPECT_LT(std::abs(reaction - results.pressure.total_power), power_gap * reaction)
      << reaction << " vs " << results.pressure.total_power;
  EXPECT_GT(results.power.friction, 0.0);
  // Ideal work: A₀/A_f = (π/4)/(0.5·0.5) = π for the exact circle. The mesh's
  // quarter disk is its inscribed polygon (Q1) or more (Q2 adds the parabolic
  // segments), so the bound uses the polygon: 4 pieces of π/8, ½ sin(π/8) each.
  const Real polygon_area = 4 * 0.5 * std::sin(std::numbers::pi / 8);
  EXPECT_GT(reaction, std::sqrt(3.0) * std::log(polygon_area / 0.25));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RoundBilletSquareDie,
    ::testing::Values(std::make_tuple(fem::ElementKind::Q1, assembly::ContactNormals::Faces,
                                      FrictionRegularization::Regularized),
                      std::make_tuple(fem::ElementKind::Q1, assembly::ContactNormals::Nodes,
                                      FrictionRegularization::Regularized),
                      std::make_tuple(fem::ElementKind::Q1, assembly::ContactNormals::Nodes,
                                      FrictionRegularization::None),
                      std::make_tuple(fem::ElementKind::Q2, assembly::ContactNormals::Nodes,
                                      FrictionRegularization::Regularized)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) == fem::ElementKind::Q1 ? "Q1" : "Q2") +
             (std::get<1>(info.param) == assembly::ContactNormals::Faces ? "FaceNormals"
                                                                         : "NodalNormals") +
             (std::get<2>(info.param) == FrictionRegularization::None ? "Exact" : "Regularized");
    });

} // namespace
} // namespace formflow::testing
