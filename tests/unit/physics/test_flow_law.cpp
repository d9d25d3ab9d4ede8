// SPDX-License-Identifier: MIT
// The piecewise power law (5.4): continuity, linear branches, bounds (2.11), derivative.
#include "formflow/physics/flow_law.hpp"

#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace formflow::testing {
namespace {

using physics::FlowLaw;

/// The paper's law and a strongly rate-sensitive one, where mistakes in the
/// exponent or the branch limits show up clearly.
std::vector<FlowLaw> laws() {
  FlowLaw sensitive;
  sensitive.as<physics::PiecewisePower>().A = 2.0;
  sensitive.as<physics::PiecewisePower>().alpha = 0.2;
  sensitive.rate1 = 0.1;
  sensitive.rate2 = 10.0;
  return {FlowLaw{}, sensitive};
}

/// Logarithmic sweep over twelve decades, through both break points.
std::vector<double> sweep() {
  std::vector<double> rates;
  for (double e = -6.0; e <= 6.0; e += 0.25) rates.push_back(std::pow(10.0, e));
  return rates;
}

TEST(PowerLaw, DefaultsAreThePaperValues) {
  // SPEC §1: A = √3, α = 1e-3, ε̄̇1 = 1e-3, ε̄̇2 = 1e3.
  const FlowLaw law;
  EXPECT_TRUE(approx(law.as<physics::PiecewisePower>().A, std::sqrt(3.0), 1e-15));
  EXPECT_EQ(law.as<physics::PiecewisePower>().alpha, 1e-3);
  EXPECT_EQ(law.rate1, 1e-3);
  EXPECT_EQ(law.rate2, 1e3);
}

TEST(PowerLaw, PowerLawInsideTheRange) {
  for (const FlowLaw& law : laws())
    for (double rate : {law.rate1 * 1.5, std::sqrt(law.rate1 * law.rate2), law.rate2 / 1.5})
      // pow is accurate to an ulp or two: 1e-14 relative.
      EXPECT_TRUE(approx(law.yield_stress(rate),
                         law.as<physics::PiecewisePower>().A *
                             std::pow(rate, law.as<physics::PiecewisePower>().alpha),
                         1e-14))
          << rate;
}

TEST(PowerLaw, ContinuousAtBothBreakPoints) {
  for (const FlowLaw& law : laws())
    for (double limit : {law.rate1, law.rate2}) {
      const double at = law.as<physics::PiecewisePower>().A *
                        std::pow(limit, law.as<physics::PiecewisePower>().alpha);
      EXPECT_TRUE(approx(law.yield_stress(limit), at, 1e-14));
      // One part in 1e9 either side moves σ_p by at most that much (σ_p′ ≤ σ_p/ε̄̇),
      // so 1e-8 relative separates continuity from any jump.
      EXPECT_TRUE(approx(law.yield_stress(limit * (1 - 1e-9)), at, 1e-8)) << "below " << limit;
      EXPECT_TRUE(approx(law.yield_stress(limit * (1 + 1e-9)), at, 1e-8)) << "above " << limit;
    }
}

TEST(PowerLaw, LinearThroughTheOriginOutsideTheRange) {
  for (const FlowLaw& law : laws()) {
    const double slope_low = law.as<physics::PiecewisePower>().A *
                             std::pow(law.rate1, law.as<physics::PiecewisePower>().alpha) /
                             law.rate1;
    const double slope_high = law.as<physics::PiecewisePower>().A *
                              std::pow(law.rate2, law.as<physics::PiecewisePower>().alpha) /
                              law.rate2;
    for (double factor : {1e-6, 0.01, 0.5}) {
      const double rate = law.rate1 * factor;
      EXPECT_TRUE(approx(law.yield_stress(rate), slope_low * rate, 1e-14)) << rate;
      EXPECT_TRUE(approx(law.secant_viscosity(rate), slope_low, 1e-14)) << rate;
    }
    for (double factor : {2.0, 100.0, 1e6}) {
      const double rate = law.rate2 * factor;
      EXPECT_TRUE(approx(law.yield_stress(rate), slope_high * rate, 1e-14)) << rate;
      EXPECT_TRUE(approx(law.secant_viscosity(rate), slope_high, 1e-14)) << rate;
    }
  }
}

TEST(PowerLaw, SecantViscosityIsFiniteAtRest) {
  for (const FlowLaw& law : laws()) {
    const double eta = law.secant_viscosity(0.0);
    EXPECT_TRUE(std::isfinite(eta));
    EXPECT_TRUE(approx(eta,
                       law.as<physics::PiecewisePower>().A *
                           std::pow(law.rate1, law.as<physics::PiecewisePower>().alpha - 1.0),
                       1e-14));
    EXPECT_EQ(law.yield_stress(0.0), 0.0);
    EXPECT_EQ(law.dissipation(0.0), 0.0);
  }
}

TEST(PowerLaw, BoundsOfCondition211HoldOnASweep) {
  // η1 ≤ σ_p′ ≤ σ_p/ε̄̇ ≤ η2 with η2 = σ_p(ε̄̇1)/ε̄̇1 (largest secant) and
  // η1 = α σ_p(ε̄̇2)/ε̄̇2 (smallest slope, at the top of the power range).
  for (const FlowLaw& law : laws()) {
    const double eta2 = law.as<physics::PiecewisePower>().A *
                        std::pow(law.rate1, law.as<physics::PiecewisePower>().alpha - 1.0);
    const double eta1 = law.as<physics::PiecewisePower>().alpha *
                        law.as<physics::PiecewisePower>().A *
                        std::pow(law.rate2, law.as<physics::PiecewisePower>().alpha - 1.0);
    double previous = 0.0;
    for (double rate : sweep()) {
      const double slope = law.yield_stress_derivative(rate);
      const double secant = law.secant_viscosity(rate);
      // 1e-12 relative: the comparisons are between pow() results that may tie.
      EXPECT_GE(slope, eta1 * (1 - 1e-12)) << rate;
      EXPECT_LE(slope, secant * (1 + 1e-12)) << rate;
      EXPECT_LE(secant, eta2 * (1 + 1e-12)) << rate;
      EXPECT_TRUE(approx(secant * rate, law.yield_stress(rate), 1e-14));
      EXPECT_GT(law.yield_stress(rate), previous) << "σ_p must increase: " << rate;
      previous = law.yield_stress(rate);
    }
  }
}

TEST(PowerLaw, DerivativeMatchesCentralDifferences) {
  // Relative step 1e-6: truncation ≈ h²σ_p‴/6 ~ 1e-12 relative to σ_p/ε̄̇;
  // round-off ≈ ε σ_p/h ~ 1e-10 relative to σ_p/ε̄̇. For the paper's law σ_p′
  // is α = 1e-3 times smaller than σ_p/ε̄̇, so compare with 1e-6 of the secant
  // viscosity as absolute scale: still 1000× below the derivative itself.
  for (const FlowLaw& law : laws()) {
    std::vector<double> rates = {law.rate1 * 3, std::sqrt(law.rate1 * law.rate2), law.rate2 / 3};
    rates.push_back(law.rate1 / 10); // linear branches: the slope is the secant viscosity
    rates.push_back(law.rate2 * 10);
    for (double rate : rates) {
      const double h = 1e-6 * rate;
      const double difference = (law.yield_stress(rate + h) - law.yield_stress(rate - h)) / (2 * h);
      EXPECT_TRUE(approx(law.yield_stress_derivative(rate), difference, 1e-6,
                         1e-6 * law.secant_viscosity(rate)))
          << "rate " << rate;
    }
  }
}

TEST(PowerLaw, DissipationIsStressTimesRate) {
  for (const FlowLaw& law : laws())
    for (double rate : sweep())
      EXPECT_TRUE(approx(law.dissipation(rate), law.yield_stress(rate) * rate, 1e-15));
}

TEST(PowerLaw, AlphaOneIsNewtonianEverywhere) {
  // α = 1: σ_p = A ε̄̇ on every branch, so the secant viscosity is A at all rates.
  FlowLaw law;
  law.as<physics::PiecewisePower>().A = 2.5;
  law.as<physics::PiecewisePower>().alpha = 1.0;
  for (double rate : sweep()) {
    EXPECT_TRUE(approx(law.secant_viscosity(rate), 2.5, 1e-15)) << rate;
    EXPECT_TRUE(approx(law.yield_stress_derivative(rate), 2.5, 1e-15)) << rate;
  }
  EXPECT_TRUE(approx(law.secant_viscosity(0.0), 2.5, 1e-15));
}

} // namespace
} // namespace formflow::testing
