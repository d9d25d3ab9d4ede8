// SPDX-License-Identifier: MIT
// The paper's law (eq. 5.4): σ_p = A ε̄̇^α on [rate1, rate2].
#pragma once

#include "formflow/physics/flow_laws/power_law_response.hpp"

#include <string_view>

namespace formflow::physics {

struct PiecewisePower {
  static constexpr std::string_view name = "piecewise_power";
  static constexpr bool rate_independent = false;
  Real A = 1.7320508075688772; ///< √3: shear yield k = σ_p/√3 ≈ 1
  Real alpha = 1e-3;           ///< strain-rate sensitivity, 0 < α ≤ 1
  FlowResponse at(Real rate) const { return power_law_response(A, alpha, rate); }
};

} // namespace formflow::physics
