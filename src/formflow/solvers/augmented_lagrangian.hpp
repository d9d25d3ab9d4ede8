// SPDX-License-Identifier: MIT
// Exact Coulomb friction by an augmented Lagrangian (Uzawa) loop around an inner
// nonlinear solve in which the friction multipliers are frozen.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <functional>

namespace formflow::solvers {

/// Callback receiving each iteration record (the monitor).
using IterationObserver = std::function<void(const IterationRecord&)>;

/// The inner nonlinear solve: with `multipliers` frozen, iterate from `start`
/// (null: the solver's own first iterate) under `control`, reporting every
/// iteration. Any solver that passes the multipliers to FormingProblem::assemble
/// fits (the secant iteration below; a Newton iteration later).
template <int dim>
using InnerSolve =
    std::function<SecantOutcome(const assembly::FrictionMultipliers<dim>& multipliers,
                                const VectorX* start, const IterationControl& control,
                                const IterationObserver& on_iteration)>;

template <int dim> struct AugmentedOutcome {
  /// Final velocity, stop reason and the inner iterations of all outer steps, numbered on.
  SecantOutcome solve;
  /// λ_T at the Γ3 points after the last update (what post-processing evaluates with).
  assembly::FrictionMultipliers<dim> multipliers;
  int augmentations = 0;        ///< outer (multiplier) updates
  Real multiplier_change = 0.0; ///< last ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖ in L²(Γ3)
};

/// Uzawa iteration of the augmented Lagrangian for λ_T (Alart–Curnier form):
///   solve the problem with λᵏ frozen → uᵏ;  λᵏ⁺¹ = proj_{|λ| ≤ τ_f(uᵏ)}(λᵏ + r uᵏ_T);
/// from λ⁰ = 0, each inner solve warm-started from the last velocity. Stops when the
/// inner solve has converged (velocity relative change < δ) and the multipliers
/// changed by less than δ relative in L²(Γ3); `control.max_iterations` bounds the
/// inner iterations of all outer steps together.
template <int dim>
AugmentedOutcome<dim>
augmented_lagrangian(const assembly::FormingProblem<dim>& problem, const InnerSolve<dim>& inner,
                     const IterationControl& control, const IterationObserver& on_iteration);

/// One Uzawa update λᵏ⁺¹ = proj_{|λ| ≤ τ_f(u)}(λᵏ + r u_T) at `velocity`, in place;
/// returns ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖ in L²(Γ3) (0 where there is no friction at all).
template <int dim>
Real update_friction_multipliers(const assembly::FormingProblem<dim>& problem,
                                 const VectorX& velocity,
                                 assembly::FrictionMultipliers<dim>& multipliers);

/// The secant-modulus iteration as the inner solve (same solver and timers throughout).
template <int dim>
InnerSolve<dim> secant_inner_solve(const assembly::FormingProblem<dim>& problem,
                                   LinearSolver& solver, PhaseTimes& times);

} // namespace formflow::solvers
