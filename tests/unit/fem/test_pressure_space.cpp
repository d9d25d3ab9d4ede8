// SPDX-License-Identifier: MIT
// Pressure bases of the mixed formulation: sizes, nesting, partition of unity.
#include "formflow/fem/pressure_space.hpp"

#include <gtest/gtest.h>

namespace formflow::fem {
namespace {

TEST(PressureSpace, SizesPerCell) {
  EXPECT_EQ(pressure_functions_per_cell<2>(PressureSpace::P0), 1);
  EXPECT_EQ(pressure_functions_per_cell<2>(PressureSpace::P1disc), 3);
  EXPECT_EQ(pressure_functions_per_cell<2>(PressureSpace::Q1disc), 4);
  EXPECT_EQ(pressure_functions_per_cell<2>(PressureSpace::Q1), 4);
  EXPECT_EQ(pressure_functions_per_cell<3>(PressureSpace::P1disc), 4);
  EXPECT_EQ(pressure_functions_per_cell<3>(PressureSpace::Q1disc), 8);
}

TEST(PressureSpace, P1discIsNestedInQ1discWhichAddsOnlyTheBilinearMonomial) {
  const Point<2> xi(0.3, -0.7);
  const VectorX p1 = tabulate_pressure<2>(PressureSpace::P1disc, xi);
  const VectorX q1 = tabulate_pressure<2>(PressureSpace::Q1disc, xi);
  EXPECT_DOUBLE_EQ(p1[0], 1.0);
  EXPECT_DOUBLE_EQ(p1[1], 0.3);
  EXPECT_DOUBLE_EQ(p1[2], -0.7);
  EXPECT_DOUBLE_EQ(q1[0], 1.0);
  EXPECT_DOUBLE_EQ(q1[1], 0.3);
  EXPECT_DOUBLE_EQ(q1[2], -0.7);
  EXPECT_DOUBLE_EQ(q1[3], 0.3 * -0.7);
}

TEST(PressureSpace, ContinuousQ1IsAPartitionOfUnityAndInterpolatesAtTheVertices) {
  const VectorX inside = tabulate_pressure<2>(PressureSpace::Q1, Point<2>(0.25, -0.5));
  EXPECT_NEAR(inside.sum(), 1.0, 1e-15);
  // Vertex k = (bit 0: ξ = ±1, bit 1: η = ±1), lexicographic.
  for (int k = 0; k < 4; ++k) {
    const Point<2> vertex((k & 1) ? 1.0 : -1.0, (k & 2) ? 1.0 : -1.0);
    const VectorX values = tabulate_pressure<2>(PressureSpace::Q1, vertex);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(values[j], j == k ? 1.0 : 0.0, 1e-15);
  }
}

} // namespace
} // namespace formflow::fem
