// SPDX-License-Identifier: MIT
// The one floating-point comparison helper of the test suite.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

namespace formflow::testing {

/// |actual − expected| ≤ abs_tol + rel_tol·|expected|. Every call site states
/// both tolerances and why they are what they are: a mixed test stays
/// meaningful for values near zero (abs) and for large values (rel).
inline ::testing::AssertionResult approx(double actual, double expected, double rel_tol,
                                         double abs_tol = 0.0) {
  const double bound = abs_tol + rel_tol * std::abs(expected);
  if (std::isfinite(actual) && std::abs(actual - expected) <= bound)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << actual << " differs from " << expected << " by " << std::abs(actual - expected) << " > "
         << bound << " (rel " << rel_tol << ", abs " << abs_tol << ")";
}

} // namespace formflow::testing
