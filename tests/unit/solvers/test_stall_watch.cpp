// SPDX-License-Identifier: MIT
// When a loop has stalled: a window of iterations without a new minimum of its merit.
#include "formflow/solvers/stall_watch.hpp"

#include <gtest/gtest.h>

namespace formflow::solvers {
namespace {

TEST(StallWatch, ASlowButSteadyDecreaseNeverStalls) {
  StallWatch watch(3);
  Real merit = 1.0;
  for (int k = 0; k < 200; ++k, merit *= 0.99) EXPECT_FALSE(watch.stalled(merit)) << k;
}

TEST(StallWatch, ANonMonotoneDecreaseWithinTheWindowDoesNotStall) {
  StallWatch watch(3);
  for (const Real merit : {1.0, 2.0, 3.0, 0.5, 0.6, 0.7, 0.4}) EXPECT_FALSE(watch.stalled(merit));
}

TEST(StallWatch, AWindowWithoutANewMinimumStalls) {
  StallWatch watch(3);
  EXPECT_FALSE(watch.stalled(1e-3));
  EXPECT_FALSE(watch.stalled(2e-3));
  EXPECT_FALSE(watch.stalled(1e-3)); // equal is no progress
  EXPECT_TRUE(watch.stalled(1.5e-3));
}

TEST(StallWatch, CyclingBetweenTwoValuesStalls) {
  StallWatch watch(4);
  int stalled_at = -1;
  for (int k = 0; k < 20 && stalled_at < 0; ++k)
    if (watch.stalled(k % 2 ? 2e-4 : 3e-4)) stalled_at = k;
  EXPECT_EQ(stalled_at, 5); // minimum 2e-4 at k = 1, then four iterations without one
}

// Exact stick releases a held node: the merit jumps above the old minimum (the node's
// excess) and falls again as the iterate settles; counted from the release, not from the
// old minimum.
TEST(StallWatch, ARestartCountsMinimaAfresh) {
  StallWatch watch(3);
  EXPECT_FALSE(watch.stalled(1e-6));
  EXPECT_FALSE(watch.stalled(1e-2)); // one without a new minimum
  EXPECT_FALSE(watch.stalled(8e-3)); // two
  watch.restart();
  EXPECT_FALSE(watch.stalled(9e-3)); // a new minimum after the restart
  EXPECT_FALSE(watch.stalled(5e-3));
  // Without the restart the third merit above 1e-6 would have stalled.
  StallWatch unrestarted(3);
  for (const Real merit : {1e-6, 1e-2, 8e-3}) EXPECT_FALSE(unrestarted.stalled(merit));
  EXPECT_TRUE(unrestarted.stalled(9e-3));
}

} // namespace
} // namespace formflow::solvers
