// SPDX-License-Identifier: MIT
// Exact Coulomb friction solved by Newton: multiplier updates between Newton steps.
#pragma once

#include "formflow/solvers/augmented_lagrangian.hpp"
#include "formflow/solvers/newton_iteration.hpp"

namespace formflow::solvers {

/// Exact friction (friction.regularization = "none") with solver.method = "newton":
/// the Alart–Curnier law λ_T = proj_{|λ| ≤ τ_f}(λ̂ + r u_T) with λ̂ frozen inside
/// each Newton iteration (its semismooth tangent, assembly/newton_system.cpp), and
/// the Uzawa update λ̂ ← proj(λ̂ + r u_T) after every Newton iteration (an inexact
/// augmented Lagrangian: no inner solve to δ per update). Stops when a Newton
/// iteration changed the velocity by less than δ relative AND the Coulomb residual of
/// the velocity and the updated multipliers is below δ (solvers/friction_residual.hpp);
/// Stalled when neither improves for a window of iterations. One Newton loop (one
/// analysis, duals carried on) for the whole run; `initial` as in newton_iteration.
/// AugmentedOutcome::augmentations counts the updates.
/// augment_friction (EveryIteration) around newton_iteration.
template <int dim>
AugmentedOutcome<dim> augmented_newton(FormingNonlinearProblem<dim>& problem, LinearSolver& solver,
                                       const IterationControl& control,
                                       const IterationObserver& on_iteration, PhaseTimes& times,
                                       const VectorX* initial = nullptr);

} // namespace formflow::solvers
