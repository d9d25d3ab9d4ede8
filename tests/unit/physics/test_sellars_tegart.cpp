// SPDX-License-Identifier: MIT
// The Sellars–Tegart law and a law at one point's temperature (issue 18).
#include "formflow/physics/flow_law.hpp"
#include "formflow/physics/manufactured_thermal.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace formflow::physics {
namespace {

FlowLaw sellars_tegart(Real temperature) {
  FlowLaw law;
  SellarsTegart model; // Sheppard's AA6063 constants, °C
  model.temperature = temperature;
  law.model = model;
  law.rate1 = 1e-3;
  law.rate2 = 1e3;
  return law;
}

TEST(SellarsTegart, ClosedFormAtACheckPoint) {
  // σ = asinh((Z/A)^(1/n))/α_s with Z = 1·exp(141550/(8.314·773.15)), by hand: 20.497 MPa.
  const Real z_over_a = std::exp(141550.0 / (8.314 * 773.15)) / 5.91e9;
  EXPECT_NEAR(sellars_tegart(500).yield_stress(1.0),
              std::asinh(std::pow(z_over_a, 1 / 5.385)) / 0.04, 1e-12 * 20.5);
  EXPECT_NEAR(sellars_tegart(500).yield_stress(1.0), 20.497, 1e-3);
}

TEST(SellarsTegart, SlopeIsTheDerivative) {
  // Central differences, step 1e-5 relative: truncation O(1e-10), round-off O(1e-11).
  const FlowLaw law = sellars_tegart(450);
  for (const Real rate : {1e-2, 0.3, 10.0, 300.0}) {
    const Real step = 1e-5 * rate;
    const Real numeric =
        (law.yield_stress(rate + step) - law.yield_stress(rate - step)) / (2 * step);
    EXPECT_NEAR(law.yield_stress_derivative(rate), numeric, 1e-7 * numeric) << rate;
  }
}

TEST(TemperatureSlope, IsTheDerivativeInTAtFixedRate) {
  // ∂σ_p/∂T of both hot laws against central differences in T, step 1e-2 K: the scale
  // of the T-dependence is R T²/(Q/n) ≈ 200 K, so truncation ≈ (1e-2/200)² ≈ 3e-9 relative,
  // round-off ≈ 1e-16 σ/1e-2 K; asserted to 1e-6 relative.
  const FlowLaw st = sellars_tegart(450);
  FlowLaw hs;
  HenselSpittel model;
  model.A = 400, model.m1 = -2.5e-3, model.m3 = 0.12, model.m8 = 1e-4, model.temperature = 450;
  hs.model = model;
  for (const FlowLaw* law : {&st, static_cast<const FlowLaw*>(&hs)})
    for (const Real rate : {1e-2, 0.3, 10.0, 300.0}) {
      const Real step = 1e-2;
      const Real numeric = (law_at_temperature(*law, 450 + step).yield_stress(rate) -
                            law_at_temperature(*law, 450 - step).yield_stress(rate)) /
                           (2 * step);
      EXPECT_NEAR(yield_stress_temperature_slope(*law, rate), numeric, 1e-6 * std::abs(numeric))
          << rate;
      EXPECT_LT(numeric, 0.0); // both soften as T rises
    }
}

TEST(SellarsTegart, SatisfiesConditionTwoElevenAndSoftensWithTemperature) {
  EXPECT_FALSE(check_flow_law_over(sellars_tegart(0), 300, 600).has_value());
  EXPECT_GT(sellars_tegart(400).yield_stress(1.0), sellars_tegart(500).yield_stress(1.0));
}

TEST(FlowLawAt, IsTheLawAtThatTemperatureAndLeavesOthersAlone) {
  const FlowLaw cold = sellars_tegart(400), hot = sellars_tegart(500);
  for (const Real rate : {1e-4, 0.5, 2e3}) { // below, inside and above [rate1, rate2]
    EXPECT_EQ(FlowLawAt(cold, 500).secant_viscosity(rate), hot.secant_viscosity(rate));
    EXPECT_EQ(FlowLawAt(cold, 500).yield_stress_derivative(rate),
              hot.yield_stress_derivative(rate));
  }
  const FlowLaw paper; // piecewise_power: not temperature dependent
  EXPECT_FALSE(paper.is_temperature_dependent());
  EXPECT_TRUE(cold.is_temperature_dependent());
  EXPECT_EQ(FlowLawAt(paper, 1234).secant_viscosity(0.7), paper.secant_viscosity(0.7));
}

} // namespace
} // namespace formflow::physics
