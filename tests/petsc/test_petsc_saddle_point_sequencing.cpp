// SPDX-License-Identifier: MIT
// The discontinuous pressure kept as a saddle point on the iterative PETSc path (issue
// 20): mesh sequencing (solver.coarse_levels), inexact secant steps and Anderson
// acceleration (solver.acceleration) change how the fine-mesh fixed point is reached, not
// which one: the same ram reaction within what the loop's stop and the Krylov tolerance
// leave, in fewer fine steps and fewer Krylov iterations.
#include "formflow/app/simulation.hpp"
#include "formflow/io/case.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace formflow {
namespace {

constexpr Real sequencing_delta = 1e-6;             // solver.tolerance of these runs
constexpr Real sequencing_krylov_tolerance = 1e-12; // -ksp_rtol of these runs

/// The paper case (μ = 0.1, d = 1e-3) at h = 1.25 on the iterative saddle-point path,
/// with `edits` after the common ones; the condition estimate for the tolerance.
app::Simulation run_iterative_saddle(std::vector<io::Override> edits) {
  std::vector<io::Override> all = {
      {"mesh.size", "1.25"},
      {"formulation.type", "mixed"},
      {"formulation.discontinuous_pressure", "saddle_point"},
      {"friction.mu", "0.1"},
      {"solver.method", "secant"},
      // The plain loop unless a test asks for Anderson's (the default on this path):
      // the bounds below are the plain loop's, step by step.
      {"solver.acceleration", "none"},
      {"solver.linear", "petsc"},
      {"solver.max_iterations", "1000"},
      {"solver.tolerance", fmt::format("{}", sequencing_delta)},
      {"solver.petsc_options", fmt::format("-ksp_rtol {}", sequencing_krylov_tolerance)}};
  all.insert(all.end(), edits.begin(), edits.end()); // a later override wins
  app::Simulation simulation =
      app::simulate(io::load_case("", std::move(all)), {}, /*estimate_condition=*/true);
  EXPECT_TRUE(simulation.results.converged())
      << solvers::stop_reason_name(simulation.results.stop_reason);
  return simulation;
}

/// How far a converged secant run's load may lie from the fixed point's, relative. The
/// loop stops at a change cₙ < δ; for a map contracting at ρ the last iterate is within
/// ρ/(1 − ρ) cₙ of the fixed point, ρ read from the run's last two changes (the tail of
/// the secant loop contracts at a steady rate). The last step is solved to the Krylov
/// tolerance (an inexact step never ends the loop), which errs by at most rtol/r_s on
/// the saddle point of reciprocal condition r_s. The load is the reaction of the
/// velocity, taken as erring as much as it, relative.
Real distance_to_fixed_point(const app::Simulation& simulation) {
  const auto& history = simulation.results.history;
  EXPECT_GE(history.size(), 2U);
  if (history.size() < 2) return 0;
  const Real last = history.back().relative_change;
  const Real before = history[history.size() - 2].relative_change;
  const Real contraction = std::min<Real>(0.99, last / before);
  EXPECT_TRUE(simulation.reciprocal_condition.has_value());
  const Real condition = simulation.reciprocal_condition.value_or(1.0);
  return contraction / (1 - contraction) * last + sequencing_krylov_tolerance / condition;
}

Real load_difference(const app::Simulation& a, const app::Simulation& b) {
  return std::abs(a.results.pressure.ram_reaction - b.results.pressure.ram_reaction) /
         std::abs(b.results.pressure.ram_reaction);
}

long total_krylov(const app::Simulation& simulation) {
  return simulation.results.linear_algebra.iterations;
}

/// The fine mesh starts from the coarse levels' solution interpolated to it (levels
/// solved by CHOLMOD Newton on the condensed pressure, d > 0): the same fine problem and
/// stop rule, so the same fixed point, reached in fewer fine secant steps than from the
/// constant-viscosity start.
TEST(SaddlePointSequencing, CoarseStartGivesTheSameLoadInFewerFineSteps) {
  const app::Simulation from_constant = run_iterative_saddle({{"solver.coarse_levels", "0"}});
  const app::Simulation sequenced = run_iterative_saddle({{"solver.coarse_levels", "2"}});
  const Real tolerance =
      distance_to_fixed_point(from_constant) + distance_to_fixed_point(sequenced);
  std::cout << "fine secant steps " << from_constant.results.iterations << " from constant "
            << "viscosity, " << sequenced.results.iterations << " sequenced ("
            << sequenced.results.coarse_mesh_sizes.size() << " coarse levels); load difference "
            << load_difference(sequenced, from_constant) << " (tolerance " << tolerance << ")\n";
  ASSERT_FALSE(sequenced.results.coarse_mesh_sizes.empty()); // a coarse level ran
  EXPECT_TRUE(from_constant.results.coarse_mesh_sizes.empty());
  EXPECT_LT(sequenced.results.iterations, from_constant.results.iterations);
  EXPECT_LE(load_difference(sequenced, from_constant), tolerance);
  EXPECT_EQ(sequenced.results.method, "saddle point (petsc) around secant from coarse meshes");
}

/// Far from δ a secant step's Krylov solve only reduces the residual of its start (the
/// last iterate) by 1e-2; the steps that may end the loop are solved to -ksp_rtol.
/// `-formflow_inexact_steps 0` solves every step to -ksp_rtol: the same fixed point, so
/// the same load within both runs' distances to it, and more Krylov iterations.
TEST(SaddlePointSequencing, InexactStepsGiveTheExactStepsLoadWithFewerKrylovIterations) {
  const app::Simulation inexact = run_iterative_saddle({{"solver.coarse_levels", "0"}});
  const app::Simulation exact = run_iterative_saddle(
      {{"solver.coarse_levels", "0"},
       {"solver.petsc_options",
        fmt::format("-ksp_rtol {} -formflow_inexact_steps 0", sequencing_krylov_tolerance)}});
  const Real tolerance = distance_to_fixed_point(inexact) + distance_to_fixed_point(exact);
  std::cout << "Krylov iterations " << total_krylov(inexact) << " inexact, " << total_krylov(exact)
            << " exact; secant steps " << inexact.results.iterations << " / "
            << exact.results.iterations << "; load difference " << load_difference(inexact, exact)
            << " (tolerance " << tolerance << ")\n";
  EXPECT_LT(total_krylov(inexact), total_krylov(exact));
  EXPECT_LE(load_difference(inexact, exact), tolerance);
}

/// Anderson acceleration (solver.acceleration) mixes the loop's steps, loose ones too:
/// the same fixed point in fewer fine steps. The accelerated run's last change ratio is
/// not the map's contraction, so both runs' distances use the plain run's ρ: each final
/// iterate is one exact step G(x) from its x, within ρ/(1 − ρ) cₙ of the fixed point
/// whatever x was, plus the Krylov tolerance's rtol/r_s.
TEST(SaddlePointSequencing, AndersonGivesTheSameLoadInFewerFineSteps) {
  const app::Simulation plain = run_iterative_saddle({{"solver.coarse_levels", "0"}});
  const app::Simulation anderson =
      run_iterative_saddle({{"solver.coarse_levels", "0"}, {"solver.acceleration", "anderson"}});
  const auto& history = plain.results.history;
  ASSERT_GE(history.size(), 2U);
  const Real rho = std::min<Real>(0.99, history.back().relative_change /
                                            history[history.size() - 2].relative_change);
  ASSERT_TRUE(plain.reciprocal_condition.has_value());
  const Real krylov_reach = sequencing_krylov_tolerance / *plain.reciprocal_condition;
  const Real tolerance =
      rho / (1 - rho) *
          (history.back().relative_change + anderson.results.history.back().relative_change) +
      2 * krylov_reach;
  std::cout << "fine secant steps " << plain.results.iterations << " plain, "
            << anderson.results.iterations << " Anderson; Krylov iterations " << total_krylov(plain)
            << " / " << total_krylov(anderson) << "; load difference "
            << load_difference(anderson, plain) << " (tolerance " << tolerance << ")\n";
  EXPECT_LT(anderson.results.iterations, plain.results.iterations);
  EXPECT_LE(load_difference(anderson, plain), tolerance);
}

} // namespace
} // namespace formflow
