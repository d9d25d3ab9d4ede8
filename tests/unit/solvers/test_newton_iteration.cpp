// SPDX-License-Identifier: MIT
// Newton on a small extrusion: converges to the secant solution, faster; the
// linear-viscous law needs no iteration at all; stop reasons and phase timers.
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/newton_iteration.hpp"

#include "formflow/mesh/channel_mesh.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace formflow::testing {
namespace {

using solvers::StopReason;

/// Half channel 4 × 4 → 2 over 4 (50 % reduction like the benchmark), unit Q2 cells.
const mesh::Mesh<2>& small_mesh() {
  static const mesh::Mesh<2> m = mesh::make_channel_mesh(mesh::ChannelGeometry{4, 4, 2, 4}, 1.0, 2);
  return m;
}

solvers::SecantOutcome run(const assembly::FormingProblem<2>& problem,
                           const solvers::IterationControl& control, bool newton,
                           PhaseTimes* phase_times = nullptr, int* callbacks = nullptr) {
  auto solver = solvers::make_cholmod_solver();
  PhaseTimes local_times;
  PhaseTimes& times = phase_times ? *phase_times : local_times;
  const auto count = [&](const solvers::IterationRecord&) {
    if (callbacks) ++*callbacks;
  };
  solvers::FormingNonlinearProblem<2> nonlinear(problem);
  return newton ? solvers::newton_iteration(nonlinear, *solver, control, count, times)
                : solvers::secant_iteration(nonlinear, *solver, control, count, times);
}

TEST(NewtonIteration, ConvergesToTheSecantSolutionInFewerIterations) {
  for (double mu : {0.0, 0.2}) {
    SCOPED_TRACE(mu);
    assembly::ProblemSettings settings;
    settings.friction.mu = mu;
    const assembly::FormingProblem<2> problem(small_mesh(), settings);
    solvers::IterationControl control;
    int callbacks = 0;
    PhaseTimes times;
    const solvers::SecantOutcome newton = run(problem, control, true, &times, &callbacks);
    ASSERT_EQ(newton.stop_reason, StopReason::Converged);
    EXPECT_EQ(callbacks, static_cast<int>(newton.history.size()));
    EXPECT_GT(times.get("line search"), 0.0) << "no Newton step was taken";
    control.tolerance = 1e-9; // the referee: secant driven far below δ
    const solvers::SecantOutcome secant = run(problem, control, false);
    ASSERT_EQ(secant.stop_reason, StopReason::Converged);
    EXPECT_LT(newton.history.size() * 4, secant.history.size());
    EXPECT_LT((newton.velocity - secant.velocity).norm() / secant.velocity.norm(), 1e-4);
  }
}

TEST(NewtonIteration, LinearViscousLawIsSolvedByTheStart) {
  // m = 1: the constant-viscosity start is the solution, so the first step
  // changes nothing (to solver round-off).
  assembly::ProblemSettings settings;
  settings.law.model = physics::NortonHoff{};
  settings.law.as<physics::NortonHoff>().m = 1.0;
  const assembly::FormingProblem<2> problem(small_mesh(), settings);
  const solvers::SecantOutcome outcome = run(problem, solvers::IterationControl{}, true);
  ASSERT_EQ(outcome.stop_reason, StopReason::Converged);
  ASSERT_EQ(outcome.history.size(), 1u);
  EXPECT_LT(outcome.history[0].relative_change, 1e-9);
}

TEST(NewtonIteration, IterationLimitIsAStopReason) {
  const assembly::FormingProblem<2> problem(small_mesh(), assembly::ProblemSettings{});
  solvers::IterationControl control;
  control.max_iterations = 2;
  const solvers::SecantOutcome outcome = run(problem, control, true);
  EXPECT_EQ(outcome.stop_reason, StopReason::MaxIterations);
  EXPECT_EQ(outcome.history.size(), 2u);
  EXPECT_TRUE(outcome.velocity.allFinite());
}

} // namespace
} // namespace formflow::testing
