// SPDX-License-Identifier: MIT
// The state of the contact boundary Γ3 at one face quadrature point: what the
// contact and friction terms and the post-processing read.
#pragma once

#include "formflow/core/types.hpp"

namespace formflow::assembly {

/// State of the contact boundary Γ3 at one face quadrature point for a velocity w.
template <int dim> struct ContactPoint {
  Index facet = 0; ///< index into Mesh::facets
  Point<dim> position = Point<dim>::Zero();
  Point<dim> normal = Point<dim>::Zero();
  Real weight = 0.0;        ///< JxW
  Real normal_velocity = 0; ///< u_N = u·n (> 0: penetration into the die)
  Point<dim> tangential_velocity = Point<dim>::Zero(); ///< u_T
  Real contact_pressure = 0;                           ///< −σ_N = u_N/d_N
  Real mean_contact_pressure = 0;                      ///< σ̄_N, mollified over radius h
  Real friction_threshold = 0; ///< τ_f of friction.law (μ_f max(σ̄_N, 0), m k, …); 0 where off
  Real threshold_pressure_slope = 0; ///< ∂τ_f/∂σ̄_N at the point (Newton's dτ_f coupling)
  Real shear_yield = 0;     ///< k = σ_p(max(ε̄̇, rate1))/√3 (for laws that need it, else 0)
  Real friction_weight = 0; ///< τ_f/√(|u_T|² + d_T²); exact friction: s·r (see below)
  /// Exact friction only: the lagged part s·λ_T of the traction, a load in K u = F.
  Point<dim> friction_load = Point<dim>::Zero();
  /// λ_T = friction_weight·u_T + friction_load: the friction traction resisting the
  /// slip (σ_T = −λ_T). Regularised: τ_f u_T/√(|u_T|² + d_T²); exact: proj(λ + r u_T).
  Point<dim> friction_traction = Point<dim>::Zero();
  /// Regularised: |λ_T| < 0.99 τ_f (|u_T| < 7 d_T); exact: |λ + r u_T| ≤ τ_f. Never
  /// where τ_f = 0.
  bool sticking = false;

  /// The part of `vector` in the tangent plane at this point (a multiplier handed in
  /// from elsewhere need not be tangential).
  Point<dim> tangential_part(const Point<dim>& vector) const {
    return vector - vector.dot(normal) * normal;
  }
};

/// Exact friction at one point for the frozen multiplier λ̂ (its tangential part)
/// and τ_f = point.friction_threshold: friction_traction = proj(λ̂_T + r u_T) = s t,
/// friction_weight = s r, friction_load = s λ̂_T, sticking = |t| ≤ τ_f (τ_f > 0).
template <int dim>
void exact_friction_point(const Point<dim>& multiplier, Real augmentation,
                          ContactPoint<dim>& point);

} // namespace formflow::assembly
