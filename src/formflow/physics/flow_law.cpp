// SPDX-License-Identifier: MIT
// Piecewise power law (5.4).
#include "formflow/physics/flow_law.hpp"

#include <cmath>

namespace formflow::physics {

Real PowerLaw::secant_viscosity(Real rate) const {
  // Below rate1 and above rate2 the law is linear through the origin, so the
  // secant viscosity is constant there; inside it is A ε̄̇^(α−1).
  if (rate <= rate1) return A * std::pow(rate1, alpha - 1.0);
  if (rate >= rate2) return A * std::pow(rate2, alpha - 1.0);
  return A * std::pow(rate, alpha - 1.0);
}

Real PowerLaw::yield_stress(Real rate) const { return secant_viscosity(rate) * rate; }

Real PowerLaw::yield_stress_derivative(Real rate) const {
  if (rate < rate1 || rate > rate2) return secant_viscosity(rate);
  return alpha * A * std::pow(rate, alpha - 1.0);
}

}  // namespace formflow::physics
