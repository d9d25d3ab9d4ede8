// SPDX-License-Identifier: MIT
// Simplex rules: exactness on every monomial to the asked degree (and not beyond for the
// rules of exactly that degree), positive weights, interior points, the vertex rule.
#include "formflow/fem/simplex_quadrature.hpp"

#include "formflow/core/error.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace formflow::testing {
namespace {

constexpr double simplex_unit_roundoff = std::numeric_limits<double>::epsilon() / 2;

double simplex_factorial(int n) {
  double result = 1;
  for (int k = 2; k <= n; ++k) result *= k; // exact in double up to 18!
  return result;
}

/// ∫ over the unit simplex of Π ξ_d^{e_d} = Π e_d! / (Σ e_d + dim)! (the Dirichlet integral).
template <int dim> double simplex_monomial_integral(const std::array<int, dim>& exponents) {
  double numerator = 1;
  int total = dim;
  for (int e : exponents) {
    numerator *= simplex_factorial(e);
    total += e;
  }
  return numerator / simplex_factorial(total);
}

template <int dim> double simplex_measure_of() {
  return 1 / simplex_factorial(dim);
}

/// Every exponent vector of total degree exactly `degree`.
template <int dim> std::vector<std::array<int, dim>> simplex_exponents_of_degree(int degree) {
  std::vector<std::array<int, dim>> result;
  if constexpr (dim == 1) {
    result.push_back({degree});
  } else if constexpr (dim == 2) {
    for (int a = 0; a <= degree; ++a) result.push_back({a, degree - a});
  } else {
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b) result.push_back({a, b, degree - a - b});
  }
  return result;
}

template <int dim>
double simplex_apply_rule(const fem::QuadratureRule<dim>& rule,
                          const std::array<int, dim>& exponents) {
  double sum = 0;
  for (int q = 0; q < rule.size(); ++q) {
    double value = rule.weights[q];
    for (int d = 0; d < dim; ++d) value *= std::pow(rule.points[q][d], exponents[d]);
    sum += value;
  }
  return sum;
}

// Round-off bound for a rule of n positive weights summing to |T| ≤ 1/2 on a monomial f of
// degree k, 0 ≤ f ≤ 1 on the simplex (u the unit round-off):
//  - forming w·f (k + 1 products) and summing n positive terms: ≤ (n + k + 2)·u·|T|;
//  - the rule's own points carry absolute errors ≤ c·u, c ≈ 10 (backward-stable symmetric
//    eigensolver on a Jacobi matrix of norm ≤ 1, then a few products in the conical map),
//    moving f by ≤ |∇f|·c·u ≤ k·dim·c·u, i.e. ≤ 10·dim·k·u·|T| in the sum;
//  - the weights μ0·v0² from eigenvectors with absolute errors ≤ c·u: Σ|δw| ≤ 2c·√n·u.
template <int dim> double simplex_rule_roundoff(int n_points, int degree) {
  return simplex_unit_roundoff *
         (simplex_measure_of<dim>() * (n_points + degree + 2 + 10.0 * dim * degree) +
          20.0 * std::sqrt(static_cast<double>(n_points)));
}

/// The largest |rule − exact| over the monomials of total degree exactly `degree`.
template <int dim> double simplex_worst_error(const fem::QuadratureRule<dim>& rule, int degree) {
  double worst = 0;
  for (const auto& e : simplex_exponents_of_degree<dim>(degree))
    worst = std::max(
        worst, std::abs(simplex_apply_rule<dim>(rule, e) - simplex_monomial_integral<dim>(e)));
  return worst;
}

template <int dim> void check_simplex_exactness(int degree) {
  const fem::QuadratureRule<dim> rule = fem::simplex_rule<dim>(degree);
  const double tolerance = simplex_rule_roundoff<dim>(rule.size(), degree);
  for (int k = 0; k <= degree; ++k)
    for (const auto& e : simplex_exponents_of_degree<dim>(k))
      EXPECT_TRUE(approx(simplex_apply_rule<dim>(rule, e), simplex_monomial_integral<dim>(e), 0.0,
                         tolerance))
          << "dim " << dim << ", degree " << degree << ", monomial of degree " << k;
}

TEST(SimplexRule, ExactForEveryMonomialUpToItsDegree) {
  for (int degree = 0; degree <= 12; ++degree) {
    check_simplex_exactness<1>(degree);
    check_simplex_exactness<2>(degree);
    check_simplex_exactness<3>(degree);
  }
}

template <int dim> void check_simplex_positive_inside(int degree) {
  const fem::QuadratureRule<dim> rule = fem::simplex_rule<dim>(degree);
  ASSERT_EQ(rule.weights.size(), rule.points.size());
  for (int q = 0; q < rule.size(); ++q) {
    EXPECT_GT(rule.weights[q], 0.0) << "dim " << dim << ", degree " << degree << ", point " << q;
    for (int d = 0; d < dim; ++d) EXPECT_GT(rule.points[q][d], 0.0) << degree << ", " << q;
    EXPECT_LT(rule.points[q].sum(), 1.0) << "dim " << dim << ", degree " << degree << ", " << q;
  }
  const double total = std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0);
  EXPECT_TRUE(
      approx(total, simplex_measure_of<dim>(), 0.0, simplex_rule_roundoff<dim>(rule.size(), 0)));
}

TEST(SimplexRule, WeightsArePositiveSumToTheMeasureAndPointsAreInside) {
  for (int degree = 0; degree <= 12; ++degree) {
    check_simplex_positive_inside<1>(degree);
    check_simplex_positive_inside<2>(degree);
    check_simplex_positive_inside<3>(degree);
  }
}

TEST(SimplexRule, RuleSizesAreTheSymmetricRulesThenConicalProducts) {
  // Triangle: 1, 1, 3, 6, 6, 7, then n² with n = ⌊degree/2⌋ + 1; tetrahedron: 1, 1, 4, then n³.
  const int triangle[] = {1, 1, 3, 6, 6, 7, 16, 16, 25, 25, 36, 36, 49};
  const int tetrahedron[] = {1, 1, 4, 8, 27, 27, 64, 64, 125, 125, 216, 216, 343};
  for (int degree = 0; degree <= 12; ++degree) {
    EXPECT_EQ(fem::simplex_rule<1>(degree).size(), degree / 2 + 1) << degree;
    EXPECT_EQ(fem::simplex_rule<2>(degree).size(), triangle[degree]) << degree;
    EXPECT_EQ(fem::simplex_rule<3>(degree).size(), tetrahedron[degree]) << degree;
  }
}

template <int dim> void check_simplex_not_exact_beyond(int degree) {
  // An exact rule errs by round-off, below simplex_rule_roundoff; a rule of degree d errs
  // at some monomial of degree d + 1 by a definite amount: the symmetric rules by ≥ 1e-5
  // (the centroid on ξ², 1/18 against 1/12; the others by their moment defects), the
  // conical n-point rules on ξ^{2n} by ∫ (1 − u)^{dim−1} π_n(u)² du > 0 (π_n the monic
  // Gauss–Jacobi polynomial; it falls like 16^{−n}, to about 4e-9 for the tetrahedron's
  // n = 6, the smallest tested). A hundred times the round-off bound (≤ 1e-11) separates
  // the two.
  const fem::QuadratureRule<dim> rule = fem::simplex_rule<dim>(degree);
  EXPECT_GT(simplex_worst_error<dim>(rule, degree + 1),
            100 * simplex_rule_roundoff<dim>(rule.size(), degree + 1))
      << "dim " << dim << ": the rule for degree " << degree << " is exact beyond it";
}

TEST(SimplexRule, RulesOfExactlyTheirDegreeAreNotExactOneDegreeHigher) {
  // Symmetric triangle rules of degree 1, 2, 4, 5; tetrahedron 1, 2; the conical rules
  // asked for an odd degree 2n − 1 (the segment's Gauss rules likewise).
  for (int degree : {1, 2, 4, 5, 7, 9, 11}) check_simplex_not_exact_beyond<2>(degree);
  for (int degree : {1, 2, 3, 5, 7, 9, 11}) check_simplex_not_exact_beyond<3>(degree);
  for (int degree : {1, 3, 5, 7, 9, 11}) check_simplex_not_exact_beyond<1>(degree);
}

TEST(SimplexRule, SevenPointRuleHasRadonsClosedFormPoints) {
  // The orbit of barycentric (a, a, 1 − 2a), a = (6 − √15)/21, holds the point (a, a).
  const fem::QuadratureRule<2> rule = fem::simplex_rule<2>(5);
  const double a = (6 - std::sqrt(15.0)) / 21;
  int found = 0;
  for (int q = 0; q < rule.size(); ++q)
    if (approx(rule.points[q].x(), a, 0.0, 1e-15) && approx(rule.points[q].y(), a, 0.0, 1e-15)) {
      ++found;
      // (155 − √15)/1200 of the unit area, halved for the reference triangle.
      EXPECT_TRUE(approx(rule.weights[q], (155 - std::sqrt(15.0)) / 2400, 0.0, 1e-16));
    }
  EXPECT_EQ(found, 1);
}

template <int dim> void check_simplex_vertex_rule() {
  const fem::QuadratureRule<dim> rule = fem::simplex_vertex_rule<dim>();
  ASSERT_EQ(rule.size(), dim + 1);
  EXPECT_EQ(rule.points[0], Point<dim>::Zero());
  for (int d = 0; d < dim; ++d) EXPECT_EQ(rule.points[d + 1], Point<dim>::Unit(d));
  for (int q = 0; q <= dim; ++q)
    EXPECT_TRUE(approx(rule.weights[q], simplex_measure_of<dim>() / (dim + 1), 1e-15));
  // Exact for degree ≤ 1 (the P1 functions are what it lumps), not for ξ²: it gives the
  // vertex weight measure/(dim + 1) against 2/(dim + 2)!.
  EXPECT_TRUE(approx(simplex_worst_error<dim>(rule, 0), 0.0, 0.0, 1e-16));
  EXPECT_TRUE(approx(simplex_worst_error<dim>(rule, 1), 0.0, 0.0, 1e-16));
  EXPECT_GT(simplex_worst_error<dim>(rule, 2), 1e-3);
}

TEST(SimplexVertexRule, PointsAreTheVerticesWithEqualWeights) {
  check_simplex_vertex_rule<1>();
  check_simplex_vertex_rule<2>();
  check_simplex_vertex_rule<3>();
}

TEST(SimplexRule, NegativeDegreesAreRejected) {
#if !defined(NDEBUG) || defined(FORMFLOW_ENABLE_ASSERTS)
  EXPECT_THROW(fem::simplex_rule<2>(-1), InternalError);
#else
  GTEST_SKIP() << "FF_ASSERT is compiled out in this build";
#endif
}

} // namespace
} // namespace formflow::testing
