// SPDX-License-Identifier: MIT
// Power laws on [rate1, rate2], linear through the origin outside (eq. 5.4 and issue 6).
#include "formflow/physics/flow_law.hpp"

#include <fmt/format.h>

#include <cmath>

namespace formflow::physics {

Real FlowLaw::coefficient() const {
  switch (kind) {
  case FlowLawKind::PiecewisePower: return A;
  case FlowLawKind::NortonHoff: return std::sqrt(3.0) * K * std::pow(std::sqrt(3.0), m);
  case FlowLawKind::HenselSpittel:
    return hs_A * std::exp(hs_m1 * temperature) * std::pow(strain, hs_m2) *
           std::exp(hs_m4 / strain);
  case FlowLawKind::PerfectlyPlastic: return sigma0;
  }
  return 0.0;
}

Real FlowLaw::exponent() const {
  switch (kind) {
  case FlowLawKind::PiecewisePower: return alpha;
  case FlowLawKind::NortonHoff: return m;
  case FlowLawKind::HenselSpittel: return hs_m3 + hs_m8 * temperature;
  case FlowLawKind::PerfectlyPlastic: return 0.0;
  }
  return 0.0;
}

Real FlowLaw::secant_viscosity(Real rate) const {
  // Below rate1 and above rate2 the law is linear through the origin, so the
  // secant viscosity is constant there; inside it is C ε̄̇^(m−1).
  const Real clamped = rate <= rate1 ? rate1 : (rate >= rate2 ? rate2 : rate);
  return coefficient() * std::pow(clamped, exponent() - 1.0);
}

Real FlowLaw::yield_stress(Real rate) const {
  return secant_viscosity(rate) * rate;
}

Real FlowLaw::yield_stress_derivative(Real rate) const {
  if (rate < rate1 || rate > rate2) return secant_viscosity(rate);
  return exponent() * coefficient() * std::pow(rate, exponent() - 1.0);
}

FlowLaw::SecantAndDerivative FlowLaw::secant_viscosity_and_derivative(Real rate) const {
  const Real viscosity = secant_viscosity(rate);
  // Inside [rate1, rate2] σ_p′ = m C ε̄̇^(m−1) = m ν; outside, the linear branch: σ_p′ = ν.
  if (rate < rate1 || rate > rate2) return {viscosity, viscosity};
  return {viscosity, exponent() * viscosity};
}

std::optional<std::string> check_flow_law(const FlowLaw& law) {
  const Real c = law.coefficient(), m = law.exponent();
  if (!(std::isfinite(c) && c > 0))
    return fmt::format("the law's coefficient C = {:g} of σ_p = C ε̄̇^m is not a positive number", c);
  if (!(m >= 0 && m <= 1))
    return fmt::format("its rate exponent m = {:g} is outside [0, 1]: {}", m,
                       m > 1 ? "σ_p′ > σ_p/ε̄̇, the secant viscosity would grow with ε̄̇"
                             : "σ_p would decrease with ε̄̇");
  const bool rate_independent = law.kind == FlowLawKind::PerfectlyPlastic;
  Real eta1 = INFINITY, eta2 = 0.0;
  const Real low = std::log10(law.rate1) - 1.0, high = std::log10(law.rate2) + 1.0;
  for (int k = 0; k <= 200; ++k) {
    const Real rate = std::pow(10.0, low + (high - low) * k / 200.0);
    const Real slope = law.yield_stress_derivative(rate), secant = law.secant_viscosity(rate);
    if (!(std::isfinite(slope) && std::isfinite(secant)))
      return fmt::format("σ_p is not finite at ε̄̇ = {:g}", rate);
    if (slope > secant * (1.0 + 1e-12))
      return fmt::format("σ_p′ = {:g} exceeds σ_p/ε̄̇ = {:g} at ε̄̇ = {:g}", slope, secant, rate);
    eta1 = std::min(eta1, slope);
    eta2 = std::max(eta2, secant);
  }
  if (eta1 < 0 || (eta1 == 0 && !rate_independent))
    return fmt::format("min σ_p′ = {:g}: σ_p must increase (η1 > 0)", eta1);
  return std::nullopt;
}

} // namespace formflow::physics
