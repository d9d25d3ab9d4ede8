// SPDX-License-Identifier: MIT
// Norton–Hoff: s = 2K(√3 ε̄̇)^(m−1) ė, i.e. σ_p = √3 K (√3 ε̄̇)^m.
#pragma once

#include "formflow/physics/flow_laws/power_law_response.hpp"

#include <string_view>

namespace formflow::physics {

/// m = 1 is linear viscous (σ_p = 3K ε̄̇, K the shear viscosity).
struct NortonHoff {
  static constexpr std::string_view name = "norton_hoff";
  static constexpr bool rate_independent = false;
  Real K = 1.0; ///< consistency (stress·time^m)
  Real m = 0.1; ///< rate sensitivity, 0 < m ≤ 1
  FlowResponse at(Real rate) const {
    return power_law_response(std::sqrt(3.0) * K * std::pow(std::sqrt(3.0), m), m, rate);
  }
};

} // namespace formflow::physics
