// SPDX-License-Identifier: MIT
// Body force and heat source of the coupled manufactured solution, by the chain rule.
#include "formflow/physics/manufactured_thermal.hpp"

#include "formflow/core/error.hpp"
#include "formflow/physics/kinematics.hpp"

#include <cmath>
#include <numbers>
#include <variant>

namespace formflow::physics {

namespace {
constexpr Real pi = std::numbers::pi;
} // namespace

Real ManufacturedTemperature::value(const Point<2>& x) const {
  return base_ + rise_ * std::sin(0.5 * pi * x[0]) * (1.0 + 0.5 * std::cos(pi * x[1]));
}

Point<2> ManufacturedTemperature::gradient(const Point<2>& x) const {
  const Real s = std::sin(0.5 * pi * x[0]), c = std::cos(0.5 * pi * x[0]);
  return Point<2>(rise_ * 0.5 * pi * c * (1.0 + 0.5 * std::cos(pi * x[1])),
                  -rise_ * s * 0.5 * pi * std::sin(pi * x[1]));
}

Real ManufacturedTemperature::laplacian(const Point<2>& x) const {
  const Real s = std::sin(0.5 * pi * x[0]);
  return rise_ * s *
         (-0.25 * pi * pi * (1.0 + 0.5 * std::cos(pi * x[1])) -
          0.5 * pi * pi * std::cos(pi * x[1]));
}

FlowLaw law_at_temperature(FlowLaw law, Real temperature) {
  std::visit(
      [&](auto& model) {
        if constexpr (TemperatureDependent<std::decay_t<decltype(model)>>)
          model.temperature = temperature;
      },
      law.model);
  return law;
}

Real yield_stress_temperature_slope(const FlowLaw& law, Real rate) {
  FF_ASSERT(rate >= law.rate1 && rate <= law.rate2,
            "the exact temperature slope is the law's own, inside [rate1, rate2]");
  return std::visit(
      [&](const auto& model) -> Real {
        if constexpr (TemperatureDependent<std::decay_t<decltype(model)>>)
          return model.temperature_slope(rate);
        else
          return 0.0;
      },
      law.model);
}

Point<2> coupled_body_force(const FlowLaw& law, const StreamFunctionField& field,
                            const ManufacturedTemperature& temperature, const Point<2>& x) {
  const FlowLaw local = law_at_temperature(law, temperature.value(x));
  const Tensor2<2> gradient = field.gradient(x);
  Point<2> force = viscous_body_force<2>(local, gradient, field.hessians(x));
  const Tensor3 rate = strain_rate<2>(gradient);
  const Real rate_bar = equivalent_strain_rate(rate);
  // τ_ik = ⅔ ν ε̇_ik with ν = σ_p/ε̄̇: −∂_k τ_ik gains −⅔ (∂ν/∂T) ∂_k T ε̇_ik.
  const Real viscosity_slope = yield_stress_temperature_slope(local, rate_bar) / rate_bar;
  const Point<2> grad_t = temperature.gradient(x);
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k) force[i] -= 2.0 / 3.0 * viscosity_slope * grad_t[k] * rate(i, k);
  return force;
}

Real coupled_heat_source(const FlowLaw& law, const Thermal& thermal,
                         const StreamFunctionField& field,
                         const ManufacturedTemperature& temperature, const Point<2>& x) {
  const FlowLaw local = law_at_temperature(law, temperature.value(x));
  const Real rate_bar = equivalent_strain_rate(strain_rate<2>(field.gradient(x)));
  return thermal.volumetric_heat() * field.velocity(x).dot(temperature.gradient(x)) -
         thermal.conductivity * temperature.laplacian(x) -
         thermal.taylor_quinney * local.dissipation(rate_bar);
}

} // namespace formflow::physics
