// SPDX-License-Identifier: MIT
// The manufactured-solution ladder that needs h = 1/128 to reach its asymptotic L2 order.
#include "verification/verification_support.hpp"

#include <gtest/gtest.h>

namespace formflow {
namespace {

TEST(ManufacturedLong, Q1OnSmoothlyDistortedMeshWithPowerLawReachesSecondOrderInL2) {
  // Observed L2 orders on this ladder: 1.53, 1.53, 1.63, 1.77, 1.89 (h = 1/8 … 1/128).
  const post::StudyTable table = testing::mesh_ladder({1.0 / 64, 1.0 / 128}, [](Real size) {
    return testing::manufactured_case(fem::ElementKind::Q1, size, mesh::Distortion::Smooth, true);
  });
  ASSERT_TRUE(table.all_converged());
  const post::StudyRung& finest = table.rungs.back();
  ASSERT_TRUE(finest.order_v && finest.order_l2);
  EXPECT_NEAR(*finest.order_v, 1.0, 0.15);
  EXPECT_NEAR(*finest.order_l2, 2.0, 0.15);
}

} // namespace
} // namespace formflow
