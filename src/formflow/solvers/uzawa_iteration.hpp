// SPDX-License-Identifier: MIT
// The secant iteration with exact constraints: augmented-Lagrangian (Uzawa)
// steps on the multipliers inside each secant step (issue 5).
#pragma once

#include "formflow/solvers/secant_iteration.hpp"

namespace formflow::solvers {

/// Like secant_iteration, for a problem whose attached ConstraintMultipliers
/// enforce d = 0 and/or d_N = 0. Each secant step assembles and factorises
/// K_r(uⁿ) (the viscous matrix plus the augmentation r Bᵀ M⁻¹ B, r N Nᵀ) once,
/// then repeats {solve, update the multipliers, re-assemble the load} with the
/// same factorisation until the multipliers change by less than
/// Formulation::uzawa_tolerance (or uzawa_max_steps). The secant step counts
/// as converged only when ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ and the Uzawa steps converged.
template <int dim>
SecantOutcome
uzawa_secant_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                       const IterationControl& control,
                       const std::function<void(const IterationRecord&)>& on_iteration,
                       PhaseTimes& times);

} // namespace formflow::solvers
