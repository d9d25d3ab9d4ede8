// SPDX-License-Identifier: MIT
// Tresca's (constant shear, "friction factor") threshold τ_f = m k.
#pragma once

#include "formflow/physics/friction_threshold.hpp"

namespace formflow::physics {

/// τ_f = m k with the friction factor 0 ≤ m ≤ 1 and k the shear yield stress of the
/// workpiece at the point (m = 1: sticking friction, the interface shears like the
/// metal). It does not depend on the contact pressure, so it also acts where the
/// contact is unloaded; the usual model of hot forming with lubricant breakdown.
struct TrescaThreshold {
  Real m = 0.0;
  static constexpr bool needs_shear_yield = true;
  bool vanishes() const { return m <= 0; }
  ThresholdValue at(const ThresholdPoint& point) const { return {m * point.shear_yield, 0.0, m}; }
};

} // namespace formflow::physics
