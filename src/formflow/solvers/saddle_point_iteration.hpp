// SPDX-License-Identifier: MIT
// The secant iteration of the mixed problem with a continuous (Taylor–Hood)
// pressure: one global saddle-point solve per step (issue 5).
#pragma once

#include "formflow/solvers/secant_iteration.hpp"

namespace formflow::solvers {

/// Like secant_iteration, for a problem whose attached ConstraintMultipliers
/// carry a global pressure (has_global_pressure). Each secant step assembles
/// the velocity matrix A(uⁿ) and factorises the saddle-point matrix
/// [A Bᵀ; B −d M] (assembly::SaddlePointSystem) with `solver`, which must take
/// full, indefinite matrices (make_umfpack_solver); the pattern is analysed once.
/// The step solves for uⁿ⁺¹ and the pressure correction together; d = 0 needs
/// nothing else. With d_N = 0 the contact multipliers get Uzawa steps around
/// the same factorisation (as in uzawa_secant_iteration), and the step counts as
/// converged only when they have settled. Stop rule, records and timers as in
/// secant_iteration; the pressure ends in the multipliers (global_pressure).
template <int dim>
SecantOutcome
saddle_point_secant_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                              const IterationControl& control,
                              const std::function<void(const IterationRecord&)>& on_iteration,
                              PhaseTimes& times);

} // namespace formflow::solvers
