// SPDX-License-Identifier: MIT
// Mesh ladders of the benchmark against the exact limits of SPEC §4.
#include "regression/benchmark_support.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace formflow {
namespace {

/// Ram-reaction pressure of Q2 with the 2×2 volumetric rule on mesh II / 2^k.
std::vector<double> ladder(physics::RamCondition ram, const std::vector<double>& sizes) {
  std::vector<double> pressures;
  for (double size : sizes) {
    const post::Results results = testing::solve_benchmark([&](io::Case& c) {
      c.process.ram = ram;
      c.mesh.size = size;
    });
    EXPECT_TRUE(results.converged()) << "h = " << size;
    pressures.push_back(results.pressure.ram_reaction);
  }
  return pressures;
}

TEST(SlipLineLimit, StickingRamConvergesToHillsCentredFan) {
  // Hill's centred-fan field for a frictionless square die at 50 % reduction:
  // p = (1 + π/2) k with k = 1 (SPEC §4). It is the exact answer when the
  // billet behind the plastic zone may stay rigid, i.e. with a sticking ram.
  const double slip_line = 1.0 + std::numbers::pi / 2.0;
  const std::vector<double> p = ladder(physics::RamCondition::Sticking, {1.0, 0.5, 0.25, 0.125});
  for (std::size_t k = 1; k < p.size(); ++k) EXPECT_LT(p[k], p[k - 1]) << "rung " << k;
  EXPECT_TRUE(testing::approx(p.back(), slip_line, 0.02)); // issue 2: last rung within 2 %
  EXPECT_TRUE(testing::approx(testing::richardson_limit(p[1], p[2], p[3]), slip_line, 0.01));
}

TEST(SlipLineLimit, SlidingRamFallsBelowThreeBlockBound) {
  // With the paper's frictionless ram three rigid blocks dissipate 25 k per unit
  // ram speed over a ram height of 10: the limit pressure is at most 2.5 k.
  const double three_block_bound = 2.5;
  const std::vector<double> p = ladder(physics::RamCondition::Sliding, {1.0, 0.5, 0.25, 0.125});
  for (std::size_t k = 1; k < p.size(); ++k) EXPECT_LT(p[k], p[k - 1]) << "rung " << k;
  EXPECT_LT(p.back(), 2.6);
  EXPECT_LE(testing::richardson_limit(p[1], p[2], p[3]), three_block_bound);
}

} // namespace
} // namespace formflow
