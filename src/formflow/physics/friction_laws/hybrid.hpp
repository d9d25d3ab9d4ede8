// SPDX-License-Identifier: MIT
// The hybrid (Orowan / Shaw) threshold τ_f = min(μ max(σ̄_N, 0), m k).
#pragma once

#include "formflow/physics/friction_laws/coulomb.hpp"
#include "formflow/physics/friction_laws/tresca.hpp"

namespace formflow::physics {

/// Coulomb at low contact pressure, capped by Tresca where μσ̄_N would exceed the
/// interface's shear strength m k (high-pressure zones near the die).
struct HybridThreshold {
  Real mu = 0.0, m = 0.0;
  static constexpr bool needs_shear_yield = true;
  bool vanishes() const { return mu <= 0 || m <= 0; }
  ThresholdValue at(const ThresholdPoint& point) const {
    const ThresholdValue coulomb = CoulombThreshold{mu}.at(point);
    const ThresholdValue tresca = TrescaThreshold{m}.at(point);
    return coulomb.value <= tresca.value ? coulomb : tresca;
  }
};

} // namespace formflow::physics
