// SPDX-License-Identifier: MIT
// The whole run (app::simulate, as `formflow run` does it) with exact friction:
// the augmented-Lagrangian path is taken, and the contact output is honest.
#include "regression/benchmark_support.hpp"

#include <gtest/gtest.h>

namespace formflow {
namespace {

TEST(ExactFrictionRun, ReportsStickWhereTheMetalDoesNotSlip) {
  const post::Results results = testing::solve_benchmark([](io::Case& c) {
    c.mesh.size = 10.0 / 6.0; // mesh I: a fraction of a second
    c.friction.mu = 0.2;
    c.friction.regularization = physics::FrictionRegularization::None;
  });
  ASSERT_TRUE(results.converged());
  EXPECT_GE(results.augmentation.outer_iterations, 2);     // at least one multiplier update
  EXPECT_LT(results.augmentation.friction_residual, 1e-4); // Newton's stop rule
  // One history across the outer steps, numbered 1, 2, 3, ...
  for (std::size_t i = 0; i < results.history.size(); ++i)
    EXPECT_EQ(results.history[i].iteration, static_cast<int>(i) + 1);

  // contact.csv's state column: exact friction by Newton sticks where the slip is
  // below what its stop rule resolves, |u_T| ≤ δ u⁰ (docs/friction.md "Stop rule"), and
  // the stick lengths of summary.json add up from the same points.
  int stick_rows = 0;
  for (const auto& sample : results.contact)
    if (sample.sticking) {
      ++stick_rows;
      EXPECT_LE(sample.slip_velocity, 1e-4) << "at s = " << sample.arc_length;
    } else {
      EXPECT_GT(sample.slip_velocity, 1e-4) << "at s = " << sample.arc_length;
    }
  EXPECT_GT(stick_rows, 0);
  EXPECT_GT(results.die_zones.stick_length, 0.0);
  EXPECT_GT(results.die_zones.slip_length(), 0.0);
  EXPECT_NEAR(results.die_zones.length, 5.0, 1e-12);
  EXPECT_NEAR(results.container_zones.length, 10.0, 1e-12);
}

} // namespace
} // namespace formflow
