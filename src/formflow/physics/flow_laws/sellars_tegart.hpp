// SPDX-License-Identifier: MIT
// Sellars–Tegart (Zener–Hollomon) hyperbolic-sine law of hot working.
#pragma once

#include "formflow/physics/flow_laws/power_law_response.hpp"

#include <cmath>
#include <string_view>

namespace formflow::physics {

/// σ_p = (1/α_s) asinh((Z/A)^(1/n)), Z = ε̄̇ exp(Q/(R T_abs)), T_abs = T + offset
/// (Sellars & Tegart 1966; SPEC §6). With x = (Z/A)^(1/n): dσ_p/dε̄̇ = x/(α_s n ε̄̇ √(1+x²)),
/// which is ≤ σ_p/ε̄̇ for n ≥ 1 (asinh x ≥ x/√(1+x²)), so condition (2.11) holds on
/// [rate1, rate2] at every temperature. `temperature` is the T of the isothermal form;
/// a thermal run replaces it at every quadrature point (physics/flow_law.hpp FlowLawAt).
struct SellarsTegart {
  static constexpr std::string_view name = "sellars_tegart";
  static constexpr bool rate_independent = false;
  Real alpha = 0.040;            ///< α_s (1/stress)
  Real n = 5.385;                ///< stress exponent (≥ 1)
  Real activation = 141550.0;    ///< Q (energy/mol)
  Real A = 5.91e9;               ///< A (1/time)
  Real gas_constant = 8.314;     ///< R (energy/(mol·K))
  Real temperature = 0.0;        ///< T in the case's temperature unit
  Real absolute_offset = 273.15; ///< T_abs = T + offset (thermal.temperature_unit: °C)
  /// ln of Z/A at unit rate: Q/(R T_abs) − ln A (kept in logs: Z reaches 1e15 and beyond).
  Real log_z_over_a_unit_rate() const {
    return activation / (gas_constant * (temperature + absolute_offset)) - std::log(A);
  }
  FlowResponse at(Real rate) const {
    const Real x = std::exp((std::log(rate) + log_z_over_a_unit_rate()) / n);
    const Real stress = std::asinh(x) / alpha;
    return {stress / rate, x / (alpha * n * rate * std::sqrt(1.0 + x * x))};
  }
  /// ∂σ_p/∂T at fixed rate: ∂x/∂T = −x Q/(n R T_abs²), so ∂σ_p/∂T = −x Q/(α_s n R T_abs²
  /// √(1+x²)) (the coupled manufactured solution's body force needs it exactly).
  Real temperature_slope(Real rate) const {
    const Real x = std::exp((std::log(rate) + log_z_over_a_unit_rate()) / n);
    const Real absolute = temperature + absolute_offset;
    return -x * activation /
           (alpha * n * gas_constant * absolute * absolute * std::sqrt(1.0 + x * x));
  }
};

} // namespace formflow::physics
