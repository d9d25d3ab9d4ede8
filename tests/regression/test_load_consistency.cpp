// SPDX-License-Identifier: MIT
// The ram reaction equals the total discrete power at convergence, for every
// element, volumetric rule and friction coefficient (issue 2, "Done when").
#include "regression/benchmark_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

namespace formflow {
namespace {

using Variant = std::tuple<fem::ElementKind, int, double>; // element, volumetric rule, μ

class LoadConsistency : public ::testing::TestWithParam<Variant> {};

/// |reaction − total power| / reaction for the variant solved to `tolerance`.
double discrepancy(const Variant& variant, double tolerance) {
  const auto [element, rule, mu] = variant;
  const post::Results results = testing::solve_benchmark([&](io::Case& c) {
    c.element = element;
    c.volumetric_points = rule;
    c.friction.mu = mu;
    c.mesh.size = 10.0 / 6.0; // mesh I keeps the 18 variants × 2 tolerances fast
    c.solver.tolerance = tolerance;
    c.solver.max_iterations = 5000;
    // The bounds below follow from the secant iteration's linear contraction;
    // Newton (the default) stops on a different curve (see docs/benchmarks.md).
    c.solver.method = solvers::NonlinearMethod::Secant;
  });
  EXPECT_TRUE(results.converged());
  return std::abs(results.pressure.ram_reaction - results.pressure.total_power) /
         results.pressure.ram_reaction;
}

TEST_P(LoadConsistency, ReactionEqualsTotalPowerToIterationTolerance) {
  // At a fixed point K(u)u = F, so uᵀK(u)u = u⁰·reaction exactly; an iterate
  // stopped at relative change δ of a linearly converging iteration (observed
  // contraction ≈ 0.95) is within ≈ δ/(1 − 0.95) = 20δ of the fixed point.
  // Both bounds must hold: a missing or wrong term in either measure would
  // leave a discrepancy that does not shrink with δ.
  const double loose = discrepancy(GetParam(), 1e-4);
  const double tight = discrepancy(GetParam(), 1e-7);
  EXPECT_LT(loose, 20 * 1e-4);
  EXPECT_LT(tight, 20 * 1e-7);
}

INSTANTIATE_TEST_SUITE_P(
    EveryElementRuleAndFriction, LoadConsistency,
    ::testing::Combine(::testing::Values(fem::ElementKind::Q1, fem::ElementKind::Q2),
                       ::testing::Values(1, 2, 3), ::testing::Values(0.0, 0.1, 0.2)));

} // namespace
} // namespace formflow
