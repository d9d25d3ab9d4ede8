// SPDX-License-Identifier: MIT
// The mixed formulation end to end (issue 5): Remark 5.1 on the whole solve, the
// exact constraints (Uzawa) against the perturbed problems as d, d_N → 0, and
// the power balance with the pressure load.
#include "formflow/app/simulation.hpp"
#include "support/approx.hpp"
#include "verification/checkerboard.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace formflow {
namespace {

using testing::approx;

/// The case of solve() below, as a full simulation (`estimate_condition`: with rcond).
app::Simulation simulate(const std::function<void(io::Case&)>& edit, bool estimate_condition) {
  io::Case case_;
  case_.process.ram = physics::RamCondition::Sticking;
  case_.mesh.size = 2.5; // 4 + 2 cells across: seconds, not minutes
  // The same (secant) iteration on both sides, so that equal formulations give
  // equal iterates; the mixed and Uzawa paths run the secant method anyway.
  case_.solver.method = solvers::NonlinearMethod::Secant;
  edit(case_);
  return app::simulate(case_, {}, estimate_condition);
}

post::Results solve(const std::function<void(io::Case&)>& edit) {
  return simulate(edit, false).results;
}

void mixed(io::Case& case_, fem::PressureSpace space, Real d) {
  case_.formulation.type = assembly::FormulationType::Mixed;
  case_.formulation.pressure = space;
  case_.penalty.d = d;
}

TEST(MixedFormulation, Q1OnePointPenaltyAndQ1P0GiveTheSameSolution) {
  const app::Simulation penalty_run = simulate(
      [](io::Case& c) {
        c.element = fem::ElementKind::Q1;
        c.mesh.size = 1.0;
        c.volumetric_points = 1;
      },
      true);
  const post::Results& penalty = penalty_run.results;
  const post::Results q1p0 = solve([](io::Case& c) {
    c.element = fem::ElementKind::Q1;
    c.mesh.size = 1.0;
    mixed(c, fem::PressureSpace::P0, 1e-3);
  });
  ASSERT_TRUE(penalty.converged());
  ASSERT_TRUE(q1p0.converged());
  EXPECT_EQ(penalty.iterations, q1p0.iterations);
  // Same matrices up to round-off (the condensed P0 block sums the one-point
  // penalty's terms in another order), so the same iterates: each secant solve
  // differs by its forward error, ≲ ε·κ(K) relative with κ = 1/rcond at the
  // solution, and the linear contraction of the secant loop keeps that from
  // growing across iterations; 10 covers the iterations' accumulation. The
  // pressures are K-weighted sums of u: the same relative bound, ten times more
  // for the cell pressures (1/d times a divergence: one more cancellation).
  ASSERT_TRUE(penalty_run.reciprocal_condition);
  const double round_off =
      10 * std::numeric_limits<double>::epsilon() / *penalty_run.reciprocal_condition;
  EXPECT_TRUE(approx(q1p0.pressure.ram_reaction, penalty.pressure.ram_reaction, round_off));
  EXPECT_TRUE(approx(q1p0.pressure.mean_hydrostatic_near_ram,
                     penalty.pressure.mean_hydrostatic_near_ram, round_off));
  EXPECT_LT((q1p0.fields.cell_hydrostatic_stress - penalty.fields.cell_hydrostatic_stress).norm(),
            10 * round_off * penalty.fields.cell_hydrostatic_stress.norm());
  EXPECT_LT((q1p0.fields.velocity - penalty.fields.velocity).norm(),
            round_off * penalty.fields.velocity.norm());
  std::printf("Q1 one-point penalty vs Q1-P0: rcond %.3e, reaction difference %.3e (bound %.3e)\n",
              *penalty_run.reciprocal_condition,
              std::abs(q1p0.pressure.ram_reaction - penalty.pressure.ram_reaction) /
                  penalty.pressure.ram_reaction,
              round_off);
}

TEST(MixedFormulation, ExactIncompressibilityIsTheLimitOfThePerturbedMixedProblem) {
  // Two independent paths: Uzawa steps for d = 0, cell-wise condensation for d > 0.
  // Thm 3.4: ‖u_d − u‖ ≤ C d, so d = 1e-7 must agree with d = 0 to ~1e-6.
  const post::Results exact = solve([](io::Case& c) { mixed(c, fem::PressureSpace::P1disc, 0.0); });
  const post::Results perturbed =
      solve([](io::Case& c) { mixed(c, fem::PressureSpace::P1disc, 1e-7); });
  ASSERT_TRUE(exact.converged());
  ASSERT_TRUE(perturbed.converged());
  EXPECT_TRUE(approx(exact.pressure.ram_reaction, perturbed.pressure.ram_reaction, 1e-4));
  EXPECT_LT((exact.fields.velocity - perturbed.fields.velocity).norm(),
            1e-4 * exact.fields.velocity.norm());
  // The constraint is met: the pressure term does no work, and the ram
  // reaction (with the pressure load) equals the total discrete power.
  EXPECT_LT(std::abs(exact.power.volumetric_penalty), 1e-6 * exact.power.total());
  EXPECT_TRUE(approx(exact.pressure.ram_reaction, exact.pressure.total_power, 1e-3));
}

TEST(MixedFormulation, ExactContactIsTheLimitOfTheContactPenalty) {
  const post::Results exact = solve([](io::Case& c) {
    c.penalty.d_n = 0.0;
    c.friction.mu = 0.1;
  });
  const post::Results perturbed = solve([](io::Case& c) {
    c.penalty.d_n = 1e-10;
    c.friction.mu = 0.1;
  });
  ASSERT_TRUE(exact.converged());
  ASSERT_TRUE(perturbed.converged());
  EXPECT_TRUE(approx(exact.pressure.ram_reaction, perturbed.pressure.ram_reaction, 1e-4));
  ASSERT_EQ(exact.contact.size(), perturbed.contact.size());
  Real largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < exact.contact.size(); ++k) {
    largest = std::max(largest, std::abs(perturbed.contact[k].contact_pressure));
    difference = std::max(difference, std::abs(exact.contact[k].contact_pressure -
                                               perturbed.contact[k].contact_pressure));
  }
  EXPECT_GT(largest, 1.0); // the die face carries the extrusion pressure
  EXPECT_LT(difference, 1e-3 * largest);
}

/// Checkerboard share of the cell pressure in the container, x < 8 (away from the die).
double container_checkerboard(fem::ElementKind element, fem::PressureSpace space, Real d,
                              Real size) {
  io::Case case_;
  case_.process.ram = physics::RamCondition::Sticking;
  case_.element = element;
  case_.mesh.size = size;
  mixed(case_, space, d);
  const app::Simulation simulation = app::simulate(case_);
  EXPECT_TRUE(simulation.results.converged());
  const double share = testing::checkerboard_share(
      simulation.plane_mesh(), size, simulation.results.fields.cell_hydrostatic_stress, 8.0);
  const VectorX filtered = testing::filter_checkerboard(
      simulation.plane_mesh(), size, simulation.results.fields.cell_hydrostatic_stress);
  EXPECT_LT(testing::checkerboard_share(simulation.plane_mesh(), size, filtered, 8.0), 1e-12);
  std::printf("%s-%s h = %g: checkerboard share %.3e\n",
              std::string(fem::element_name(element)).c_str(),
              std::string(fem::pressure_space_name(space)).c_str(), size, share);
  return share;
}

TEST(MixedFormulation, Q1P0PressureHasACheckerboardThatDoesNotShrinkWithTheMesh) {
  const double q1p0_coarse =
      container_checkerboard(fem::ElementKind::Q1, fem::PressureSpace::P0, 1e-3, 1.0);
  const double q1p0_fine =
      container_checkerboard(fem::ElementKind::Q1, fem::PressureSpace::P0, 1e-3, 0.5);
  const double q2_coarse =
      container_checkerboard(fem::ElementKind::Q2, fem::PressureSpace::P1disc, 0.0, 1.0);
  const double q2_fine =
      container_checkerboard(fem::ElementKind::Q2, fem::PressureSpace::P1disc, 0.0, 0.5);
  // A smooth pressure's cell means carry a checkerboard share O(h²) (O(h) near
  // singular points): halving h must at least halve it. Q1–P0's spurious mode
  // is O(1): it does not shrink.
  EXPECT_GT(q1p0_fine, 0.5 * q1p0_coarse);
  EXPECT_LT(q2_fine, 0.5 * q2_coarse);
}

TEST(MixedFormulation, UzawaStepsStopAtTheirRoundOffFloorOnTheWedgeDrawingCase) {
  // Q2–P1disc with d = 0 on the shipped wedge-die drawing case: the multiplier
  // change settles between 1e-8 and 1e-7 (round-off amplified by the augmentation),
  // above formulation.uzawa_tolerance = 1e-8. Before the floor was recognised every
  // secant step spent all its Uzawa steps and the run took minutes.
  const std::string path = std::string(FORMFLOW_SOURCE_DIR) + "/cases/wedge-die-drawing.toml";
  io::Case case_ = io::load_case(
      path, {{"formulation.type", "mixed"}, {"penalty.d", "0"}, {"solver.max_iterations", "150"}});
  const post::Results results = app::simulate(case_).results;
  ASSERT_TRUE(results.converged());
  // Settled multipliers: the reaction is the total power of the exactly
  // incompressible field, as for every converged Uzawa run.
  EXPECT_TRUE(approx(results.pressure.ram_reaction, results.pressure.total_power, 1e-4));
  // Against the penalty problem on the same mesh (d = 1e-3): the same limit up to O(d).
  const post::Results penalty = app::simulate(io::load_case(path, {})).results;
  ASSERT_TRUE(penalty.converged());
  EXPECT_NEAR(results.pressure.ram_reaction, penalty.pressure.ram_reaction,
              2e-3 * penalty.pressure.ram_reaction);
}

} // namespace
} // namespace formflow
