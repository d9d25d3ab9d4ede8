// SPDX-License-Identifier: MIT
// Coulomb's threshold τ_f = μ max(σ̄_N, 0) (SPEC §1, eq. 3.14).
#pragma once

#include "formflow/physics/friction_threshold.hpp"

namespace formflow::physics {

/// τ_f = μ_f max(σ̄_N, 0): a tensile mean pressure carries no friction.
struct CoulombThreshold {
  Real mu = 0.0;
  static constexpr bool needs_shear_yield = false;
  bool vanishes() const { return mu <= 0; }
  ThresholdValue at(const ThresholdPoint& point) const {
    if (point.mean_contact_pressure <= 0) return {};
    return {mu * point.mean_contact_pressure, mu, 0.0};
  }
};

} // namespace formflow::physics
