// SPDX-License-Identifier: MIT
// The laws of material.law besides the paper's: closed forms inside [rate1, rate2],
// linear continuation outside, derivatives against finite differences, and the
// load-time check of condition (2.11).
#include "formflow/physics/flow_law.hpp"

#include "support/approx.hpp"
#include "support/flow_laws.hpp"

#include <gtest/gtest.h>

#include <tuple>

#include <cmath>
#include <vector>

namespace formflow::testing {
namespace {

using physics::FlowLaw;

std::vector<FlowLaw> all_laws() {
  return {FlowLaw{}, norton_hoff(0.8, 0.2), norton_hoff(0.8, 1.0), hensel_spittel(),
          perfectly_plastic(2.5)};
}

TEST(FlowLaws, NortonHoffIsRootThreeKTimesRootThreeRateToTheM) {
  const FlowLaw law = norton_hoff(0.8, 0.2);
  for (double rate : {0.01, 1.0, 50.0})
    EXPECT_TRUE(approx(law.yield_stress(rate),
                       std::sqrt(3.0) * 0.8 * std::pow(std::sqrt(3.0) * rate, 0.2), 1e-14));
}

TEST(FlowLaws, NortonHoffWithMOneIsLinearViscousEverywhere) {
  // s = 2K ė and σ_p = 3K ε̄̇ on every branch: the secant viscosity is 3K at all rates.
  const FlowLaw law = norton_hoff(0.8, 1.0);
  for (double rate : {0.0, 1e-6, 1e-3, 1.0, 1e3, 1e6}) {
    EXPECT_TRUE(approx(law.secant_viscosity(rate), 2.4, 1e-14)) << rate;
    EXPECT_TRUE(approx(law.yield_stress_derivative(rate), 2.4, 1e-14)) << rate;
  }
}

TEST(FlowLaws, HenselSpittelIsothermalForm) {
  const FlowLaw law = hensel_spittel();
  const double T = 700.0, strain = 0.5;
  for (double rate : {0.01, 1.0, 50.0}) {
    const double expected = 300.0 * std::exp(-0.002 * T) * std::pow(strain, 0.1) *
                            std::exp(-0.01 / strain) * std::pow(rate, 0.05 + 1e-4 * T);
    EXPECT_TRUE(approx(law.yield_stress(rate), expected, 1e-13)) << rate;
  }
}

TEST(FlowLaws, PerfectlyPlasticIsConstantInTheRangeAndLinearOutside) {
  const FlowLaw law = perfectly_plastic(2.5);
  for (double rate : {2e-3, 1.0, 900.0}) {
    EXPECT_EQ(law.yield_stress(rate), 2.5) << rate;
    EXPECT_EQ(law.yield_stress_derivative(rate), 0.0) << rate;
  }
  EXPECT_TRUE(approx(law.yield_stress(1e-4), 2.5 * 1e-4 / law.rate1, 1e-14));
  EXPECT_TRUE(approx(law.yield_stress(1e4), 2.5 * 1e4 / law.rate2, 1e-14));
}

TEST(FlowLaws, EveryLawIsContinuousAtTheBreakPoints) {
  for (const FlowLaw& law : all_laws())
    for (double limit : {law.rate1, law.rate2}) {
      const double at = law.yield_stress(limit);
      // σ_p′ ≤ σ_p/ε̄̇: one part in 1e9 moves σ_p by at most that much.
      EXPECT_TRUE(approx(law.yield_stress(limit * (1 - 1e-9)), at, 1e-8));
      EXPECT_TRUE(approx(law.yield_stress(limit * (1 + 1e-9)), at, 1e-8));
    }
}

TEST(FlowLaws, DerivativesMatchCentralDifferences) {
  // Relative step 1e-6 (see test_flow_law.cpp for the error budget); absolute
  // scale 1e-6 of the secant viscosity covers laws whose σ_p′ is much smaller.
  for (const FlowLaw& law : all_laws())
    for (double rate : {law.rate1 / 10, law.rate1 * 3, 1.0, law.rate2 / 3, law.rate2 * 10}) {
      const double h = 1e-6 * rate;
      const double difference = (law.yield_stress(rate + h) - law.yield_stress(rate - h)) / (2 * h);
      EXPECT_TRUE(approx(law.yield_stress_derivative(rate), difference, 1e-6,
                         1e-6 * law.secant_viscosity(rate)))
          << law.name() << " rate " << rate;
    }
}

TEST(FlowLaws, EveryDefaultAndExampleLawPassesCondition211) {
  for (const FlowLaw& law : all_laws()) EXPECT_FALSE(physics::check_flow_law(law).has_value());
  // Every registered law at its default parameters.
  const auto check = [](const auto& defaults) {
    FlowLaw law;
    law.model = defaults;
    EXPECT_FALSE(physics::check_flow_law(law).has_value()) << defaults.name;
  };
  std::apply([&](const auto&... defaults) { (check(defaults), ...); }, physics::FlowLaws::Tuple{});
}

TEST(FlowLaws, LawsViolatingCondition211AreRefused) {
  FlowLaw steep = hensel_spittel();
  steep.as<physics::HenselSpittel>().m8 = 3e-3; // m3 + m8 T = 2.15: σ_p′ > σ_p/ε̄̇
  ASSERT_TRUE(physics::check_flow_law(steep).has_value());
  EXPECT_NE(physics::check_flow_law(steep)->find("exceeds 1"), std::string::npos);
  FlowLaw softening = hensel_spittel();
  softening.as<physics::HenselSpittel>().m3 = -0.2; // σ_p decreasing in ε̄̇
  EXPECT_TRUE(physics::check_flow_law(softening).has_value());
  FlowLaw flat = hensel_spittel();
  flat.as<physics::HenselSpittel>().m3 = 0.0;
  flat.as<physics::HenselSpittel>().m8 =
      0.0; // rate-independent through the Hensel–Spittel door: η1 = 0, refused
  EXPECT_TRUE(physics::check_flow_law(flat).has_value());
  FlowLaw overflow = hensel_spittel();
  overflow.as<physics::HenselSpittel>().m1 = 5.0; // e^(3500): not a number
  EXPECT_TRUE(physics::check_flow_law(overflow).has_value());
}

} // namespace
} // namespace formflow::testing
