// SPDX-License-Identifier: MIT
// Hensel–Spittel, isothermal at temperature T and a fixed reference strain ε.
#pragma once

#include "formflow/physics/flow_laws/power_law_response.hpp"

#include <string_view>

namespace formflow::physics {

/// σ_p = A e^(m1 T) ε^m2 e^(m4/ε) ε̄̇^(m3 + m8 T); the steady-state model carries no
/// strain history, so ε is a parameter.
struct HenselSpittel {
  static constexpr std::string_view name = "hensel_spittel";
  static constexpr bool rate_independent = false;
  Real A = 1.7320508075688772, m1 = 0.0, m2 = 0.0, m3 = 0.1, m4 = 0.0, m8 = 0.0;
  Real temperature = 0.0; ///< T of the isothermal form
  Real strain = 1.0;      ///< reference equivalent strain ε > 0
  Real coefficient() const {
    return A * std::exp(m1 * temperature) * std::pow(strain, m2) * std::exp(m4 / strain);
  }
  Real exponent() const { return m3 + m8 * temperature; }
  FlowResponse at(Real rate) const { return power_law_response(coefficient(), exponent(), rate); }
  /// ∂σ_p/∂T at fixed rate: σ_p (m1 + m8 ln ε̄̇).
  Real temperature_slope(Real rate) const {
    return at(rate).viscosity * rate * (m1 + m8 * std::log(rate));
  }
};

} // namespace formflow::physics
