// SPDX-License-Identifier: MIT
// The uniaxial yield limit σ_p(ε̄̇) and its secant viscosity (SPEC §1, eq. 5.4).
#pragma once

#include "formflow/core/types.hpp"

namespace formflow::physics {

/// σ_p = A ε̄̇^α on [rate1, rate2], continued linearly through the origin
/// outside, so that η1 ≤ σ_p′ ≤ σ_p/ε̄̇ ≤ η2 (paper eq. 5.4, condition 2.11).
struct PowerLaw {
  Real A = 1.7320508075688772;  ///< √3: shear yield k = σ_p/√3 ≈ 1
  Real alpha = 1e-3;            ///< strain-rate sensitivity, 0 < α ≤ 1
  Real rate1 = 1e-3;            ///< lower limit of the power-law range
  Real rate2 = 1e3;             ///< upper limit of the power-law range

  /// Uniaxial yield limit σ_p at equivalent strain rate `rate` ≥ 0.
  Real yield_stress(Real rate) const;
  /// Secant viscosity σ_p(ε̄̇)/ε̄̇, finite at ε̄̇ = 0 (the linear branch).
  Real secant_viscosity(Real rate) const;
  /// dσ_p/dε̄̇ (one-sided at the break points).
  Real yield_stress_derivative(Real rate) const;
  /// Plastic dissipation density σ_p(ε̄̇)·ε̄̇.
  Real dissipation(Real rate) const { return yield_stress(rate) * rate; }
};

}  // namespace formflow::physics
