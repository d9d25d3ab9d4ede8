// SPDX-License-Identifier: MIT
// Kachanov's secant-modulus iteration (SPEC §3, eq. 5.2/5.3).
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <functional>
#include <vector>

namespace formflow::solvers {

struct SecantOutcome {
  VectorX velocity; ///< the last iterate (full dof vector)
  StopReason stop_reason = StopReason::MaxIterations;
  std::vector<IterationRecord> history;
};

/// From the constant-viscosity solution u⁰, solves K(uⁿ) uⁿ⁺¹ = F(uⁿ) until
/// ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ. The pattern is analysed once; each iteration
/// refactorises. Phases "assembly", "analysis", "factorization", "solve" are timed.
/// `multipliers` (exact friction) are held fixed and passed to every assembly;
/// `start` replaces the constant-viscosity first iterate (a warm start).
template <int dim>
SecantOutcome secant_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const std::function<void(const IterationRecord&)>& on_iteration,
                               PhaseTimes& times,
                               const assembly::FrictionMultipliers<dim>* multipliers = nullptr,
                               const VectorX* start = nullptr);

} // namespace formflow::solvers
