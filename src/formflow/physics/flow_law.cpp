// SPDX-License-Identifier: MIT
// Selecting the case's law, and condition (2.11).
#include "formflow/physics/flow_law.hpp"

#include <fmt/format.h>

#include <cmath>

namespace formflow::physics {

FlowLaw FlowLawChoice::selected() const {
  FlowLaw law;
  law.rate1 = rate1;
  law.rate2 = rate2;
  std::apply(
      [&](const auto&... candidates) {
        ((candidates.name == this->law ? void(law.model = candidates) : void()), ...);
      },
      parameters);
  return law;
}

std::optional<std::string> check_flow_law(const FlowLaw& law) {
  // Inside the range every law's σ_p must be a positive, finite, increasing function
  // whose slope does not exceed its secant (m ≤ 1 for a power law).
  const FlowResponse low = law.response(law.rate1);
  if (!(std::isfinite(low.viscosity) && low.viscosity > 0))
    return fmt::format("σ_p(rate1) = {:g} is not a positive number", low.viscosity * law.rate1);
  const bool rate_independent = law.is_rate_independent();
  Real eta1 = INFINITY, eta2 = 0.0;
  const Real from = std::log10(law.rate1) - 1.0, to = std::log10(law.rate2) + 1.0;
  for (int k = 0; k <= 200; ++k) {
    const Real rate = std::pow(10.0, from + (to - from) * k / 200.0);
    const Real slope = law.yield_stress_derivative(rate), secant = law.secant_viscosity(rate);
    if (!(std::isfinite(slope) && std::isfinite(secant)))
      return fmt::format("σ_p is not finite at ε̄̇ = {:g}", rate);
    if (slope > secant * (1.0 + 1e-12))
      return fmt::format("its rate exponent exceeds 1: σ_p′ = {:g} exceeds σ_p/ε̄̇ = {:g} at "
                         "ε̄̇ = {:g}, the secant viscosity would grow with ε̄̇",
                         slope, secant, rate);
    if (slope < 0)
      return fmt::format("its rate exponent is negative: σ_p would decrease with ε̄̇ (σ_p′ = {:g} "
                         "at ε̄̇ = {:g})",
                         slope, rate);
    eta1 = std::min(eta1, slope);
    eta2 = std::max(eta2, secant);
  }
  if (eta1 == 0 && !rate_independent)
    return fmt::format("min σ_p′ = {:g}: σ_p must increase (η1 > 0)", eta1);
  return std::nullopt;
}

std::optional<std::string> check_flow_law_over(const FlowLaw& law, Real low, Real high) {
  for (int k = 0; k <= 20; ++k) {
    const Real temperature = low + (high - low) * k / 20.0;
    FlowLaw at = law;
    std::visit(
        [&](auto& model) {
          if constexpr (TemperatureDependent<std::decay_t<decltype(model)>>)
            model.temperature = temperature;
        },
        at.model);
    if (auto violation = check_flow_law(at))
      return fmt::format("at T = {:g}: {}", temperature, *violation);
  }
  return std::nullopt;
}

} // namespace formflow::physics
