// SPDX-License-Identifier: MIT
// Newton–Raphson with the consistent tangent for the regularised penalty problem (eq. 3.19).
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <functional>

namespace formflow::solvers {

/// Starts like secant_iteration from the constant-viscosity solution u⁰, then
/// solves J(uⁿ) δ = −R(uⁿ) with a symmetric tangent (τ_f frozen at uⁿ; see
/// assembly/newton_system.cpp) and sets uⁿ⁺¹ = uⁿ + t δ, t from a line search on
/// the dissipation potential (a zero of δ·R(uⁿ + t δ), regula falsi).
///
/// The tangent is the primal–dual one (Chan, Golub & Mulet 1999 for TV; Rudi,
/// Shih & Stadler 2017 for viscoplastic Stokes): with σ_p nearly constant (the
/// paper's α = 1e-3) the exact tangent is 1000× softer along ė than across it
/// and the potential is nearly |ε̇| with a kink smoothed only below ε̄̇₁, so the
/// plain Newton step is damped to t ≈ 0.03–0.3 for many iterations. Carrying
/// the stress w ≈ ν ė and the slip direction λ ≈ u_T/s as separate variables,
/// updated by their own Newton step and capped to the yield surface, removes
/// that (measured on mesh II: 20 → 9 iterations to 1e-8 with μ = 0, and with
/// friction from no convergence in 40 to 14).
///
/// Safeguard: while the relative change exceeds control.newton_start (the first
/// iteration always: it starts from the constant-viscosity solution), and
/// whenever the tangent is not positive definite or δ is no descent direction,
/// a secant step K(uⁿ) uⁿ⁺¹ = F is taken instead. Stop rule as in the secant
/// iteration, ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ, where for a Newton step the change is the
/// larger of the step taken and the undamped correction ‖δ‖/‖uⁿ⁺¹‖, so that a
/// short damped step is never mistaken for convergence. Times the secant
/// phases plus "line search" and "dual update".
template <int dim>
SecantOutcome newton_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const std::function<void(const IterationRecord&)>& on_iteration,
                               PhaseTimes& times);

}  // namespace formflow::solvers
