// SPDX-License-Identifier: MIT
// The adaptive run's cheap cycles: calibrated predictions, and the endgame after the
// first prediction that may stop.
#include "formflow/app/cheap_cycles.hpp"
#include "formflow/post/load_error_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace formflow::app {
namespace {

/// A full estimate with settled change `change`, tail ratio ½ and, if given, a
/// regularisations' offset.
post::LoadErrorEstimate full_estimate(Real change, std::optional<Real> offset = std::nullopt) {
  post::LoadErrorEstimate full;
  full.enriched_change = change;
  full.ratio = 0.5;
  full.penalty_change = offset;
  return full;
}

TEST(CheapCycles, PredictTheFullEstimateFromTheCalibratingRatio) {
  CheapCycles plan;
  EXPECT_FALSE(plan.next_cycle_cheap()) << "uncalibrated: every cycle full";
  // Cycle 0 of the adaptive ram: settled −0.12933 against linearised −0.04929.
  plan.calibrate(full_estimate(-0.12933, 4e-4), -0.04929);
  EXPECT_TRUE(plan.next_cycle_cheap());
  // A later linearised change of −0.002: ρ Δ_lin = −0.12933/0.04929 × 0.002, and the
  // prediction is that change's whole tail F_s |ρ Δ_lin| / (1 − q) plus the offset.
  const Real change = -0.12933 / 0.04929 * 0.002;
  const CheapCycles::Prediction far = plan.predict(-0.002, 2.58, 1e-3);
  // The same formula on the same numbers on both sides: each side rounds at most 5 times
  // (the ratio, the product, F_s·|Δ|, the division by 1 − q, the sum of two positive
  // terms), each within u = ε/2 relative, so they differ by at most 10u = 5ε relative.
  EXPECT_NEAR(far.estimate, post::discretisation_tail(change, 0.5) + 4e-4,
              6 * std::numeric_limits<Real>::epsilon() * far.estimate);
  EXPECT_FALSE(far.may_stop) << far.estimate << " against 0.00258";
  // The refined mesh's own predicted error (half the tail here, plus the offset) within
  // the target may stop, although the cycle's own is not: the run may end there.
  const Real refined = post::tail_beyond_refined(change, 0.5) + 4e-4;
  const Real target = 1.01 * refined / std::abs(2.58 + change);
  const CheapCycles::Prediction near = plan.predict(-0.002, 2.58, target);
  EXPECT_GT(near.estimate, target * 2.58);
  EXPECT_TRUE(near.may_stop);
}

TEST(CheapCycles, ARatioThatIsNotPositiveAndFiniteLeavesEveryCycleFull) {
  for (const Real linearised : {0.0, 0.01, std::numeric_limits<Real>::quiet_NaN()}) {
    CheapCycles plan;
    plan.calibrate(full_estimate(-0.1), linearised);
    EXPECT_FALSE(plan.next_cycle_cheap()) << linearised;
  }
}

TEST(CheapCycles, AfterAPredictionCallsForTheFullEstimateEveryCycleIsFull) {
  CheapCycles plan;
  plan.calibrate(full_estimate(-0.06095), -0.02662); // Hill's 30° wedge, cycle 0
  ASSERT_TRUE(plan.next_cycle_cheap());
  plan.prediction_called_for_full_estimate();
  EXPECT_FALSE(plan.next_cycle_cheap());
  // A later calibration does not bring the cheap cycles back.
  plan.calibrate(full_estimate(-0.01168), -0.000666);
  EXPECT_FALSE(plan.next_cycle_cheap());
}

} // namespace
} // namespace formflow::app
