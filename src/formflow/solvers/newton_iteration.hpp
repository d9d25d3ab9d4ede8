// SPDX-License-Identifier: MIT
// Newton–Raphson with the consistent tangent for the regularised penalty problem (eq. 3.19).
#pragma once

#include "formflow/core/timer.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"
#include "formflow/solvers/secant_iteration.hpp"

namespace formflow::solvers {

/// Starts like secant_iteration from the constant-viscosity solution u⁰, then
/// solves J(uⁿ) δ = −R(uⁿ) and sets uⁿ⁺¹ = uⁿ + t δ, t from a line search on the
/// slope δ·R(uⁿ + t δ) (regula falsi). J = T + N: T symmetric (assembled,
/// factorised by CHOLMOD), N the unsymmetric rest of the exact Jacobian (the
/// full-ε̇ a-form's ν′ ε̇_V term and the derivative of the nonlocal τ_f, see
/// assembly/newton_system.cpp), applied matrix free; when N ≠ 0 the step comes
/// from GMRES preconditioned by T's factor (solvers/coupled_tangent_solve.hpp):
/// still one factorisation per iteration, plus a few triangular solves ("krylov").
///
/// T is the primal–dual tangent (Chan, Golub & Mulet 1999 for TV; Rudi, Shih &
/// Stadler 2017 for viscoplastic Stokes): with σ_p nearly constant (the paper's
/// α = 1e-3) the exact tangent is 1000× softer along ė than across it, so a
/// primal Newton step blows the near-rigid zones apart. Carrying the stress w ≈ ν ė
/// and the slip direction λ ≈ u_T/s as separate variables, updated by their own
/// Newton step and capped to the yield surface, removes that. The first iteration
/// is a Newton step from u⁰ with the stress the constant-viscosity solve balanced
/// as w (NonlinearProblem::secant_duals, solvers/newton_duals.hpp): below yield in the near-rigid
/// zones, so the tangent is stiff there (measured on mesh II, μ = 0: 9 → 7 iterations to δ = 1e-4
/// against a secant first step followed by the primal tangent).
///
/// Safeguard: whenever the tangent is not positive definite or δ is no descent
/// direction, and afterwards while the relative change exceeds
/// control.newton_start, a secant step K(uⁿ) uⁿ⁺¹ = F is taken instead (the duals
/// then restart from the stress that step balanced). Stop rule as in the secant
/// iteration, ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ, where for a Newton step the change is the
/// larger of the step taken and the undamped correction ‖δ‖/‖uⁿ⁺¹‖, so that a
/// short damped step is never mistaken for convergence. Times the secant
/// phases plus "krylov", "line search" and "dual update".
///
/// `initial` (full dof vector; its prescribed values are replaced by the problem's)
/// replaces the constant-viscosity solve, e.g. a coarse-mesh solution prolonged
/// (app/coarse_start.hpp). The duals start as in the usual start, from the
/// constant-viscosity stress at that velocity, w = ν(initial_rate) ė(initial) capped
/// to yield: stiff in the near-rigid zones. (The primal stress there, at yield in
/// the plastic zones, made the tangent α-soft along ė and the tail linear: measured
/// at 77 762 dofs 10, 10, 11 iterations for μ = 0, 0.1, 0.2 against 6, 6, 6.)
///
/// The problem's after-iteration hook (exact friction's multiplier updates,
/// solvers/augmented_newton.hpp) runs after every iteration; the loop converges
/// only once it reports settled. While the hook changes the problem, the tangent
/// is not assembled ahead with the trial duals (it would hold the old multipliers).
SecantOutcome newton_iteration(NonlinearProblem& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const IterationObserver& on_iteration, PhaseTimes& times,
                               const VectorX* initial = nullptr);

} // namespace formflow::solvers
