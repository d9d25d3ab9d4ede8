// SPDX-License-Identifier: MIT
// The outer Kachanov loop shared by the plain, Uzawa and saddle-point secant
// iterations: they differ only in how one linear problem with the lagged
// viscosity is solved (a LaggedSolve), not in how iterations are recorded,
// monitored and stopped.
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/stop_rule.hpp"
#include "formflow/solvers/uzawa_update.hpp"

#include "formflow/core/error.hpp"

#include <chrono>

namespace formflow::solvers {

SecantSolve::SecantSolve(NonlinearProblem& problem, TimedLinearStep& linear, bool uzawa_steps)
    : problem_(problem), linear_(linear),
      uzawa_(uzawa_steps ? problem.uzawa_limits() : std::nullopt),
      system_(problem.plan().make_system()) {
  FF_ASSERT(!uzawa_steps || uzawa_, "Uzawa steps need exact-constraint multipliers");
}

LaggedStep SecantSolve::solve(const VectorX* w, VectorX& next) {
  const int max_steps = uzawa_ ? uzawa_->max_steps : 1;
  LaggedStep result{std::nullopt, !uzawa_};
  UzawaSettling settling(uzawa_ ? uzawa_->tolerance : 0.0);
  for (int step = 0; step < max_steps; ++step) {
    {
      ScopedTimer timer(linear_.times(), "assembly");
      problem_.assemble_secant(w, system_); // Uzawa: same matrix each step; the load changes
    }
    if (step == 0) {
      if (const auto stop = linear_.analyse_once(system_.matrix)) return {stop, false};
      if (const auto stop = linear_.factorize(system_.matrix)) return {stop, false};
    }
    VectorX free_velocity;
    if (const auto stop = linear_.solve(system_.rhs, free_velocity)) return {stop, false};
    next = problem_.plan().expand(free_velocity, problem_.prescribed_values());
    if (!uzawa_) break;
    if (const auto stop = uzawa_update(problem_, next, settling, result.constraints_converged))
      return {stop, false};
    if (result.constraints_converged) break;
  }
  return result;
}

SecantOutcome secant_iteration(NonlinearProblem& problem, LaggedSolve& lagged,
                               const IterationControl& control,
                               const IterationObserver& on_iteration, const VectorX* start) {
  SecantOutcome outcome;
  outcome.velocity = problem.prescribed_values(); // u = 0 except prescribed values
  if (start) {
    outcome.velocity = *start;
  } else if (const LaggedStep first = lagged.solve(nullptr, outcome.velocity); first.stop) {
    outcome.stop_reason = *first.stop;
    return outcome;
  }
  for (int iteration = 1; iteration <= control.max_iterations; ++iteration) {
    const auto start_time = std::chrono::steady_clock::now();
    VectorX next;
    const LaggedStep step = lagged.solve(&outcome.velocity, next);
    if (step.stop) {
      outcome.stop_reason = *step.stop;
      return outcome;
    }
    const Real change = (next - outcome.velocity).norm() / next.norm();
    IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    record.pressure = problem.driven_force(lagged.system(), next) / problem.driven_height();
    record.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    outcome.velocity = std::move(next);
    outcome.history.push_back(record);
    if (on_iteration) on_iteration(record);
    const auto own = stop_after_iteration(change, change, record.pressure, control.tolerance,
                                          step.constraints_converged);
    const AfterIteration after = problem.after_iteration(
        {iteration, &outcome.velocity, own == StopReason::Converged, change});
    if (const auto stop = stop_with_hook(own, after)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
  }
  outcome.stop_reason = StopReason::MaxIterations;
  return outcome;
}

SecantOutcome secant_iteration(NonlinearProblem& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const IterationObserver& on_iteration, PhaseTimes& times,
                               const VectorX* start) {
  TimedLinearStep linear(solver, times);
  SecantSolve lagged(problem, linear);
  return secant_iteration(problem, lagged, control, on_iteration, start);
}

} // namespace formflow::solvers
