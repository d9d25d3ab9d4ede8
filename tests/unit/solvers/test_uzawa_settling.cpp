// SPDX-License-Identifier: MIT
// When Uzawa steps end: below the tolerance, or stalled at a round-off floor below √tolerance.
#include "formflow/solvers/uzawa_settling.hpp"

#include <gtest/gtest.h>

namespace formflow::solvers {
namespace {

TEST(UzawaSettling, ContractingChangesSettleOnlyBelowTheTolerance) {
  UzawaSettling settling(1e-8);
  for (const Real change : {1e-2, 1e-4, 1e-6, 5e-8}) {
    EXPECT_FALSE(settling.settled(change)) << change;
    EXPECT_FALSE(settling.converged());
  }
  EXPECT_TRUE(settling.settled(5e-9));
  EXPECT_TRUE(settling.converged());
}

TEST(UzawaSettling, AStallBelowTheSquareRootOfTheToleranceIsTheRoundOffFloor) {
  UzawaSettling settling(1e-8);
  EXPECT_FALSE(settling.settled(1e-3));
  EXPECT_FALSE(settling.settled(3e-8));
  EXPECT_TRUE(settling.settled(4e-8)); // no longer falls, and 4e-8 < 1e-4
  EXPECT_TRUE(settling.converged());
}

TEST(UzawaSettling, AStallAboveTheSquareRootOfTheToleranceIsNotConvergence) {
  UzawaSettling settling(1e-8);
  EXPECT_FALSE(settling.settled(1e-2));
  EXPECT_FALSE(settling.settled(1e-3));
  EXPECT_FALSE(settling.settled(2e-3)); // stalled, but far from any round-off floor
  EXPECT_FALSE(settling.converged());
}

} // namespace
} // namespace formflow::solvers
