// SPDX-License-Identifier: MIT
// The residual of the exact Coulomb conditions on Γ3, at the scale of the problem.
//
// Why not ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖, the multiplier change the loop used to wait for: that is
// the Alart–Curnier residual λ − proj(λ + r u_T) at the algorithm's augmentation
// r = 100/d_N = 1e8, so at a stuck point it is r |u_T|: a slip of 1e-12 u⁰ counts as a
// traction error of 1e-4. The loop then ran on while the velocity changed by < 1e-12
// and the load was settled to 7 digits (issue 16: mesh II, h = 0.5, μ = 0.2, 200
// iterations, exit 3), for traction patterns of the near-rigid dead-metal zone that
// alternate from point to point and barely load the nodes (three Gauss points per Q2
// face against two tangential dofs). The AC residual is a valid measure of the
// Coulomb conditions for every r > 0; which r sets the accuracy it asks for. Taking
// the problem's own ratio r̄ = ‖λ_T‖/‖u_T‖ (tractions of order τ_f, slips of order u⁰)
// makes the measure dimensionless and independent of the algorithm's r: at a stuck
// point it is the slip left there relative to the slip on Γ3, at a slip point the
// misalignment of λ_T and u_T relative to the tractions — both what δ asks of the
// velocity.
#pragma once

#include "formflow/assembly/contact_point.hpp"
#include "formflow/physics/friction.hpp"

#include <cmath>
#include <vector>

namespace formflow::solvers {

/// ‖λ − proj_{|λ| ≤ τ_f}(λ + r̄ u_T)‖ / ‖λ‖ in L²(Γ3) over the points where friction
/// acts (τ_f > 0), with λ = ContactPoint::friction_traction (the traction the
/// equilibrium was assembled with), u_T = ContactPoint::tangential_velocity and the
/// problem's scale r̄ = ‖λ‖/‖u_T‖ (0 when nothing slips: then only |λ| ≤ τ_f is tested).
/// Zero when λ = 0 everywhere (no friction, or none loaded yet). Dimensionless,
/// unchanged when λ and τ_f, or u_T, are scaled; zero exactly when (u_T, λ) satisfies
/// the Coulomb law at every point.
template <int dim> Real friction_residual(const std::vector<assembly::ContactPoint<dim>>& state) {
  Real traction_norm = 0.0, slip_norm = 0.0;
  for (const assembly::ContactPoint<dim>& point : state) {
    if (point.friction_threshold <= 0) continue;
    traction_norm += point.friction_traction.squaredNorm() * point.weight;
    slip_norm += point.tangential_velocity.squaredNorm() * point.weight;
  }
  if (!(traction_norm > 0)) return 0.0;
  const Real scale = slip_norm > 0 ? std::sqrt(traction_norm / slip_norm) : 0.0;
  Real residual = 0.0;
  for (const assembly::ContactPoint<dim>& point : state) {
    if (point.friction_threshold <= 0) continue;
    const Point<dim> trial = point.friction_traction + scale * point.tangential_velocity;
    const Real s = physics::coulomb_projection_factor(point.friction_threshold, trial.norm());
    residual += (point.friction_traction - s * trial).squaredNorm() * point.weight;
  }
  return std::sqrt(residual / traction_norm);
}

/// friction_residual with the traction at the `held` points replaced by what the Newton
/// step's reactions asked there, `asked[k]` (its tangential part; ContactPoint::
/// friction_traction is that multiplier projected onto the Coulomb disk). Why: a node the
/// step held (u_T = 0) whose reaction asks for more than τ_f gets λ̂ clipped to the disk by
/// the update, and the projected traction with u_T = 0 satisfies Coulomb exactly, while the
/// node's tangential row stays out of balance by W(|λ̂_asked| − τ_f): the projected
/// residual cannot see it (issue 16, case 228 of the grid, docs/friction.md "Session 11").
/// Judged with the asked multiplier the point contributes exactly that excess
/// λ − proj(λ) = (|λ| − τ_f)₊ λ/|λ| (u_T = 0 after a full step), and nothing where the
/// reaction lies inside the disk (there the asked and projected tractions coincide).
template <int dim>
Real held_friction_residual(std::vector<assembly::ContactPoint<dim>> state,
                            const std::vector<Point<dim>>& asked,
                            const std::vector<std::size_t>& held) {
  for (std::size_t k : held) {
    assembly::ContactPoint<dim>& point = state[k];
    point.friction_traction = point.tangential_part(asked[k]);
  }
  return friction_residual(state);
}

} // namespace formflow::solvers
