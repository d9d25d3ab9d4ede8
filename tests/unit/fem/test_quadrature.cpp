// SPDX-License-Identifier: MIT
// Gauss–Legendre rules: exactness to degree 2n−1 (and not beyond), weights, ordering.
#include "formflow/fem/quadrature.hpp"

#include "formflow/core/error.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace formflow::testing {
namespace {

/// ∫_{−1}^{1} x^k dx, by hand: 0 for odd k, 2/(k+1) for even k.
double monomial_integral(int k) {
  return k % 2 == 1 ? 0.0 : 2.0 / (k + 1);
}

// A rule of ≤ 125 points with positive weights summing to 2^dim applied to
// monomials bounded by 1 on the cube: the accumulated round-off is a few
// hundred ulps of O(1) at most, so 1e-13 absolute is round-off, not a fudge.
constexpr double quadrature_roundoff = 1e-13;

class GaussRule : public ::testing::TestWithParam<int> {};

TEST_P(GaussRule, OneDimensionalRuleIsExactToDegreeTwoNMinusOne) {
  const int n = GetParam();
  std::vector<Real> points, weights;
  fem::gauss_1d(n, points, weights);
  ASSERT_EQ(static_cast<int>(points.size()), n);
  for (int k = 0; k <= 2 * n - 1; ++k) {
    double sum = 0.0;
    for (int q = 0; q < n; ++q) sum += weights[q] * std::pow(points[q], k);
    EXPECT_TRUE(approx(sum, monomial_integral(k), 0.0, quadrature_roundoff))
        << "n " << n << ", x^" << k;
  }
}

TEST_P(GaussRule, OneDimensionalRuleIsNotExactAtDegreeTwoN) {
  // The error of the n-point rule on x^{2n} is a fixed positive multiple of
  // the 2n-th derivative (≥ 1e-3 for n ≤ 5), so a rule with more points or
  // wrong nodes posing as n points would be caught here.
  const int n = GetParam();
  std::vector<Real> points, weights;
  fem::gauss_1d(n, points, weights);
  double sum = 0.0;
  for (int q = 0; q < n; ++q) sum += weights[q] * std::pow(points[q], 2 * n);
  EXPECT_GT(std::abs(sum - monomial_integral(2 * n)), 1e-3) << "n " << n;
}

TEST_P(GaussRule, OneDimensionalPointsAreAscendingSymmetricAndInside) {
  const int n = GetParam();
  std::vector<Real> points, weights;
  fem::gauss_1d(n, points, weights);
  for (int q = 0; q < n; ++q) {
    EXPECT_GT(points[q], -1.0);
    EXPECT_LT(points[q], 1.0);
    EXPECT_GT(weights[q], 0.0);
    if (q > 0) {
      EXPECT_LT(points[q - 1], points[q]);
    }
    // Legendre roots are symmetric about 0; closed forms give it to round-off.
    EXPECT_TRUE(approx(points[q], -points[n - 1 - q], 0.0, 1e-15));
    EXPECT_TRUE(approx(weights[q], weights[n - 1 - q], 0.0, 1e-15));
  }
}

TEST_P(GaussRule, TwoDimensionalRuleIsExactForEveryMonomialUpToTwoNMinusOne) {
  const int n = GetParam();
  const fem::QuadratureRule<2> rule = fem::gauss_rule<2>(n);
  ASSERT_EQ(rule.size(), n * n);
  for (int a = 0; a <= 2 * n - 1; ++a)
    for (int b = 0; b <= 2 * n - 1; ++b) {
      double sum = 0.0;
      for (int q = 0; q < rule.size(); ++q)
        sum += rule.weights[q] * std::pow(rule.points[q].x(), a) * std::pow(rule.points[q].y(), b);
      EXPECT_TRUE(
          approx(sum, monomial_integral(a) * monomial_integral(b), 0.0, quadrature_roundoff))
          << "n " << n << ", x^" << a << " y^" << b;
    }
}

TEST_P(GaussRule, WeightsSumToTheMeasureOfTheReferenceCell) {
  const int n = GetParam();
  auto total = [](const auto& rule) {
    return std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0);
  };
  EXPECT_TRUE(approx(total(fem::gauss_rule<1>(n)), 2.0, 0.0, quadrature_roundoff));
  EXPECT_TRUE(approx(total(fem::gauss_rule<2>(n)), 4.0, 0.0, quadrature_roundoff));
  EXPECT_TRUE(approx(total(fem::gauss_rule<3>(n)), 8.0, 0.0, quadrature_roundoff));
}

TEST_P(GaussRule, TensorPointsAreLexicographicWithXFastest) {
  const int n = GetParam();
  std::vector<Real> points, weights;
  fem::gauss_1d(n, points, weights);
  const fem::QuadratureRule<3> rule = fem::gauss_rule<3>(n);
  ASSERT_EQ(rule.size(), n * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int q = (k * n + j) * n + i;
        EXPECT_EQ(rule.points[q].x(), points[i]);
        EXPECT_EQ(rule.points[q].y(), points[j]);
        EXPECT_EQ(rule.points[q].z(), points[k]);
        // Products of three O(1) weights: round-off.
        EXPECT_TRUE(approx(rule.weights[q], weights[i] * weights[j] * weights[k], 1e-15));
      }
}

INSTANTIATE_TEST_SUITE_P(PointsPerDirection, GaussRule,
                         ::testing::Range(1, fem::max_gauss_points + 1));

TEST(GaussRule3D, ExactForMixedMonomialsUpToTwoNMinusOne) {
  for (int n : {2, 3}) {
    const fem::QuadratureRule<3> rule = fem::gauss_rule<3>(n);
    for (int a = 0; a <= 2 * n - 1; ++a)
      for (int b = 0; b <= 2 * n - 1; ++b)
        for (int c = 0; c <= 2 * n - 1; ++c) {
          double sum = 0.0;
          for (int q = 0; q < rule.size(); ++q) {
            const Point<3>& p = rule.points[q];
            sum += rule.weights[q] * std::pow(p.x(), a) * std::pow(p.y(), b) * std::pow(p.z(), c);
          }
          const double exact = monomial_integral(a) * monomial_integral(b) * monomial_integral(c);
          EXPECT_TRUE(approx(sum, exact, 0.0, quadrature_roundoff)) << n << ": " << a << b << c;
        }
  }
}

TEST(NodalRule, PointsAreTheFaceLatticeAndTheRulesIntegrateLikeTrapezoidAndSimpson) {
  // n = 2: the corners, exact for degree 1 per direction (trapezoid); n = 3: the
  // Q2 lattice −1, 0, 1, exact for degree 3 (Simpson), not for x⁴ (2/5 vs 2/3).
  for (int n : {2, 3}) {
    const auto rule = fem::nodal_rule<2>(n);
    ASSERT_EQ(rule.size(), n * n);
    for (int q = 0; q < rule.size(); ++q) { // lexicographic, x fastest, like the nodes
      EXPECT_EQ(rule.points[q].x(), -1.0 + 2.0 * (q % n) / (n - 1));
      EXPECT_EQ(rule.points[q].y(), -1.0 + 2.0 * (q / n) / (n - 1));
    }
    const int degree = n == 2 ? 1 : 3;
    for (int a = 0; a <= degree + 1; ++a)
      for (int b = 0; b <= degree; ++b) {
        double sum = 0.0;
        for (int q = 0; q < rule.size(); ++q)
          sum +=
              rule.weights[q] * std::pow(rule.points[q].x(), a) * std::pow(rule.points[q].y(), b);
        const double exact = monomial_integral(a) * monomial_integral(b);
        if (a <= degree) {
          EXPECT_NEAR(sum, exact, 1e-14) << n << ": " << a << b;
        } else if (a % 2 == 0 && b % 2 == 0) { // odd powers integrate to 0 with any symmetric rule
          EXPECT_GT(std::abs(sum - exact), 0.1 * std::abs(exact)) << n << ": " << a << b;
        }
      }
  }
}

TEST(GaussRule1D, KnownTwoPointRule) {
  // ±1/√3 with unit weights, by hand.
  std::vector<Real> points, weights;
  fem::gauss_1d(2, points, weights);
  EXPECT_TRUE(approx(points[1], 1.0 / std::sqrt(3.0), 1e-15));
  EXPECT_TRUE(approx(weights[0], 1.0, 1e-15));
}

TEST(GaussRule1D, UnsupportedPointCountsAreRejected) {
#if !defined(NDEBUG) || defined(FORMFLOW_ENABLE_ASSERTS)
  std::vector<Real> points, weights;
  EXPECT_THROW(fem::gauss_1d(0, points, weights), InternalError);
  EXPECT_THROW(fem::gauss_1d(fem::max_gauss_points + 1, points, weights), InternalError);
#else
  GTEST_SKIP() << "FF_ASSERT is compiled out in this build";
#endif
}

} // namespace
} // namespace formflow::testing
