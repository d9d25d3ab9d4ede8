// SPDX-License-Identifier: MIT
// The friction threshold τ_f at a Γ3 point: what a friction law may depend on and
// what it returns (issue 13: friction = threshold × enforcement).
#pragma once

#include "formflow/core/types.hpp"

namespace formflow::physics {

/// What a threshold may depend on at one contact point.
struct ThresholdPoint {
  Real mean_contact_pressure = 0.0; ///< σ̄_N, the (mollified) contact pressure, compression > 0
  /// k = σ_p(max(ε̄̇, rate1))/√3, the shear yield stress of the workpiece at the point
  /// (the flow stress, not its linear continuation below rate1, so that a rigid billet
  /// still has a finite shear strength). Only filled for laws that need it.
  Real shear_yield = 0.0;
};

/// τ_f and its partial derivatives, for Newton's tangent.
struct ThresholdValue {
  Real value = 0.0;          ///< τ_f ≥ 0
  Real pressure_slope = 0.0; ///< ∂τ_f/∂σ̄_N
  Real shear_slope = 0.0;    ///< ∂τ_f/∂k
};

} // namespace formflow::physics
