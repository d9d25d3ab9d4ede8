// SPDX-License-Identifier: MIT
// Newton with mesh sequencing (solver.coarse_levels = 2: h = 0.5, 0.25, then
// 0.125) on the paper's benchmark at 77 762 dofs, μ = 0, 0.1, 0.2 (issue 6).
// Tens of seconds each: label long, run with `ctest -L long`.
#include "regression/benchmark_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace formflow {
namespace {

class CoarseStartFineMesh : public ::testing::TestWithParam<double> {};

TEST_P(CoarseStartFineMesh, ConvergesWithReactionEqualToThePower) {
  const double delta = 1e-4;
  const post::Results results = testing::solve_benchmark([](io::Case& c) {
    c.mesh.size = 0.125;
    c.friction.mu = GetParam();
    c.solver.method = solvers::NonlinearMethod::Newton;
    c.solver.coarse_levels = 2;
  });
  ASSERT_TRUE(results.converged());
  EXPECT_EQ(results.n_dofs, 77762);
  ASSERT_EQ(results.coarse_mesh_sizes.size(), 2u);
  EXPECT_DOUBLE_EQ(results.coarse_mesh_sizes[0], 0.5);
  EXPECT_DOUBLE_EQ(results.coarse_mesh_sizes[1], 0.25);
  // Issue 6's target, ≤ 8 iterations at ~100 k dofs: measured 6, 6, 6 fine
  // iterations (after 5 + 4, 5 + 4, 6 + 4 coarse ones) against 11, 13, 14 from
  // the constant-viscosity start.
  EXPECT_LE(results.iterations, 8);
  // The identity reaction = total power holds at the discrete solution. From the
  // constant-viscosity start Newton stops (δ = 1e-4) 2.3e-3 (μ = 0) and 1.5e-3
  // (μ = 0.2) away from it; from the coarse solution ≤ 2e-6 (measured). Asserted at δ.
  EXPECT_LT(std::abs(results.pressure.ram_reaction - results.pressure.total_power) /
                results.pressure.ram_reaction,
            delta);
}

INSTANTIATE_TEST_SUITE_P(PaperFrictionCoefficients, CoarseStartFineMesh,
                         ::testing::Values(0.0, 0.1, 0.2));

} // namespace
} // namespace formflow
