// SPDX-License-Identifier: MIT
// PhaseTimes: seconds per phase and how often each ran (summary.json timing_calls).
#include "formflow/core/timer.hpp"

#include <gtest/gtest.h>

namespace formflow {
namespace {

TEST(PhaseTimes, ScopedTimerAddsTimeAndCountsEachEntry) {
  PhaseTimes times;
  for (int k = 0; k < 3; ++k) ScopedTimer timer(times, "factorization");
  { ScopedTimer timer(times, "assembly"); }
  EXPECT_EQ(times.counted("factorization"), 3);
  EXPECT_EQ(times.counted("assembly"), 1);
  EXPECT_EQ(times.all().count("factorization"), 1u);
}

TEST(PhaseTimes, EventsCountWithoutTimeAndAbsentOnesAreZero) {
  PhaseTimes times;
  times.count("krylov iterations", 4);
  times.count("krylov iterations", 2);
  times.add("mesh", 0.5); // seconds only: no entry counted
  EXPECT_EQ(times.counted("krylov iterations"), 6);
  EXPECT_EQ(times.counted("mesh"), 0);
  EXPECT_EQ(times.counted("never"), 0);
  EXPECT_EQ(times.all().count("krylov iterations"), 0u); // a count is no phase
  EXPECT_DOUBLE_EQ(times.get("mesh"), 0.5);
  EXPECT_EQ(times.get("never"), 0.0);
}

} // namespace
} // namespace formflow
