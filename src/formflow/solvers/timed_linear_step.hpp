// SPDX-License-Identifier: MIT
// The one timed linear step of every nonlinear driver: analyse the pattern once,
// factorise, solve, and turn a failure into the stop reason the drivers report.
#pragma once

#include "formflow/core/timer.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <optional>

namespace formflow::solvers {

/// `solver` with the phases "analysis", "factorization" and "solve" timed into
/// `times` (summary.json timing_s and timing_calls read these names). A failed
/// analysis, factorisation or solve is SolverFailed, a non-finite solution
/// NonFinite; nothing is thrown.
class TimedLinearStep {
public:
  TimedLinearStep(LinearSolver& solver, PhaseTimes& times) : solver_(solver), times_(times) {}

  /// Symbolic analysis of `matrix`'s pattern, on the first call only (the pattern
  /// never changes during a solve).
  std::optional<StopReason> analyse_once(const assembly::SparseMatrix& matrix) {
    if (analysed_) return std::nullopt;
    analysed_ = true;
    ScopedTimer timer(times_, "analysis");
    if (!solver_.analyze(matrix)) return StopReason::SolverFailed;
    return std::nullopt;
  }

  /// Numeric factorisation (same pattern as analysed).
  std::optional<StopReason> factorize(const assembly::SparseMatrix& matrix) {
    ScopedTimer timer(times_, "factorization");
    if (!solver_.factorize(matrix)) return StopReason::SolverFailed;
    return std::nullopt;
  }

  /// Solve with the last factorisation; `solution` must come out finite.
  std::optional<StopReason> solve(const VectorX& rhs, VectorX& solution) {
    return timed_solve(rhs, solution, false);
  }
  /// The same for a right-hand side every rank holds whole (LinearSolver::solve_whole).
  std::optional<StopReason> solve_whole(const VectorX& rhs, VectorX& solution) {
    return timed_solve(rhs, solution, true);
  }

  /// Factorise `matrix`, then solve for `rhs`: the whole step.
  std::optional<StopReason> operator()(const assembly::SparseMatrix& matrix, const VectorX& rhs,
                                       VectorX& solution) {
    if (const auto stop = factorize(matrix)) return stop;
    return solve(rhs, solution);
  }

  LinearSolver& solver() { return solver_; }
  PhaseTimes& times() { return times_; }

private:
  std::optional<StopReason> timed_solve(const VectorX& rhs, VectorX& solution, bool whole) {
    {
      ScopedTimer timer(times_, "solve");
      if (!(whole ? solver_.solve_whole(rhs, solution) : solver_.solve(rhs, solution)))
        return StopReason::SolverFailed;
    }
    if (!solver_.finite(solution)) return StopReason::NonFinite;
    return std::nullopt;
  }

  LinearSolver& solver_;
  PhaseTimes& times_;
  bool analysed_ = false;
};

} // namespace formflow::solvers
