// SPDX-License-Identifier: MIT
// Newton's dual variables (the stress w ≈ ν ė and the slip direction λ) are the
// Newton driver's state: updated here from the problem's public accessors; the data
// (assembly::NewtonDuals) stays in assembly, where assemble_newton reads it.
#pragma once

#include "formflow/assembly/forming_problem.hpp"

namespace formflow::solvers {

/// The duals after the full step `step` from `u`, the iterate being `next` (full dof
/// vectors): Newton's update of w = ν ė and of λ = u_T/s, then the caps
/// √(⅔ w:w) ≤ σ_p(ε̄̇(next)) and |λ| ≤ 1 that keep the tangent positive
/// semi-definite; w = ν ė where the law is linear. Empty `duals`: start from the
/// primal choice at `u`. Exact friction: the slip dual is the scaled traction
/// λ ≈ proj(t)/τ_f, t = λ̂ + r u_T for the frozen `friction_multipliers` λ̂ (null: 0),
/// Newton-updated and capped the same way.
template <int dim>
void update_duals(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                  const VectorX& step, const VectorX& next, assembly::NewtonDuals<dim>& duals,
                  const assembly::FrictionMultipliers<dim>* friction_multipliers = nullptr);

/// The duals after a secant step from `previous` to `next`: the stress that step
/// balanced, w = ν(ε̄̇(previous)) ė(next), and the slip direction u_T(next)/s(previous),
/// with the caps of update_duals (previous = nullptr: the constant-viscosity start,
/// w = ν(initial_rate) ė, λ = 0). Where the rate has collapsed (near-rigid zones) w
/// stays far below the yield stress and the tangent stays close to the secant matrix
/// there. Exact friction: λ = t(next)/max(τ_f, |t|)(previous), capped (the traction
/// that secant step used, over τ_f).
template <int dim>
void secant_duals(const assembly::FormingProblem<dim>& problem, const VectorX* previous,
                  const VectorX& next, assembly::NewtonDuals<dim>& duals,
                  const assembly::FrictionMultipliers<dim>* friction_multipliers = nullptr);

} // namespace formflow::solvers
