// SPDX-License-Identifier: MIT
// The outer Kachanov loop shared by the secant, Uzawa and saddle-point
// iterations: they differ only in how one linear problem with the lagged
// viscosity is solved, not in how iterations are recorded, monitored and stopped.
#pragma once

#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/stop_rule.hpp"

#include <chrono>
#include <optional>

namespace formflow::solvers {

/// What one lagged solve reports: a reason to stop at once, and whether an
/// inner constraint loop (Uzawa multipliers) settled; a plain solve has none.
struct LaggedStep {
  std::optional<StopReason> stop;
  bool constraints_converged = true;
};

/// Runs uⁿ⁺¹ = solve(uⁿ) from the constant-viscosity solve(nullptr), or from
/// `start` when given, until the shared stop rule ends it. `solve(w, next)`
/// solves with the secant viscosity of w (nullptr: the constant starting one)
/// and leaves its linear system in `system`, whose reaction, pressure loads
/// included, is the monitored ram pressure.
template <int dim, typename Solve>
SecantOutcome run_lagged_iteration(const assembly::FormingProblem<dim>& problem,
                                   const assembly::LinearSystem& system,
                                   const IterationControl& control,
                                   const std::function<void(const IterationRecord&)>& on_iteration,
                                   const VectorX* start, Solve&& solve) {
  SecantOutcome outcome;
  outcome.velocity = problem.constraints().values; // u = 0 except prescribed values
  if (start) {
    outcome.velocity = *start;
  } else if (const LaggedStep first = solve(nullptr, outcome.velocity); first.stop) {
    outcome.stop_reason = *first.stop;
    return outcome;
  }
  for (int iteration = 1; iteration <= control.max_iterations; ++iteration) {
    const auto start_time = std::chrono::steady_clock::now();
    VectorX next;
    const LaggedStep step = solve(&outcome.velocity, next);
    if (step.stop) {
      outcome.stop_reason = *step.stop;
      return outcome;
    }
    const Real change = (next - outcome.velocity).norm() / next.norm();
    IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    record.pressure = problem.driven_force(system, next) / problem.driven_height();
    record.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    outcome.velocity = std::move(next);
    outcome.history.push_back(record);
    if (on_iteration) on_iteration(record);
    if (const auto stop = stop_after_iteration(change, change, record.pressure, control.tolerance,
                                               step.constraints_converged)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
  }
  outcome.stop_reason = StopReason::MaxIterations;
  return outcome;
}

} // namespace formflow::solvers
