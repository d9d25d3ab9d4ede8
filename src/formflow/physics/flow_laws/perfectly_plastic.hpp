// SPDX-License-Identifier: MIT
// The rate-independent law σ_p = σ0.
#pragma once

#include "formflow/physics/flow_laws/power_law_response.hpp"

#include <string_view>

namespace formflow::physics {

/// σ_p′ = 0 in the plastic range, so condition (2.11) holds there only with η1 = 0
/// (the α → 0 limit of eq. 5.4).
struct PerfectlyPlastic {
  static constexpr std::string_view name = "perfectly_plastic";
  static constexpr bool rate_independent = true;
  Real sigma0 = 1.7320508075688772; ///< yield stress
  FlowResponse at(Real rate) const { return {sigma0 / rate, 0.0}; }
};

} // namespace formflow::physics
