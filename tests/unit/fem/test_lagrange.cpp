// SPDX-License-Identifier: MIT
// Q1/Q2 shape functions (2D, 3D): partition of unity, nodal property, FD-checked
// gradients, polynomial reproduction, and the Gauss-point-to-node extrapolation.
#include "formflow/fem/lagrange.hpp"

#include "formflow/fem/quadrature.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace formflow::testing {
namespace {

// Shape values are products of ≤ 3 one-dimensional quadratics bounded by
// ~1.2 on the cell; sums over ≤ 27 of them are exact to a few ulps.
constexpr double lagrange_roundoff = 1e-14;

template <int dim> int n_nodes(int order) {
  int n = 1;
  for (int d = 0; d < dim; ++d) n *= order + 1;
  return n;
}

/// Reproducible sample points in the reference cell, including its corner (1,…,1).
template <int dim> std::vector<Point<dim>> sample_points() {
  std::mt19937 generator(20240611);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Point<dim>> points;
  for (int k = 0; k < 12; ++k) {
    Point<dim> xi;
    for (int d = 0; d < dim; ++d) xi[d] = uniform(generator);
    points.push_back(xi);
  }
  points.push_back(Point<dim>::Ones());
  return points;
}

/// A polynomial of degree `order` in each variable (with all mixed terms), and its gradient.
template <int dim>
double test_polynomial(int order, const Point<dim>& x, Point<dim>* gradient = nullptr) {
  // f = Π_d (c0_d + c1_d x_d + c2_d x_d²), c2 = 0 for order 1.
  const double c0[3] = {0.7, -0.3, 1.1}, c1[3] = {0.4, 1.3, -0.6}, c2[3] = {-0.8, 0.5, 0.9};
  double factor[3], derivative[3];
  for (int d = 0; d < dim; ++d) {
    const double quad = order >= 2 ? c2[d] : 0.0;
    factor[d] = c0[d] + c1[d] * x[d] + quad * x[d] * x[d];
    derivative[d] = c1[d] + 2.0 * quad * x[d];
  }
  double value = 1.0;
  for (int d = 0; d < dim; ++d) value *= factor[d];
  if (gradient)
    for (int g = 0; g < dim; ++g) {
      double partial = 1.0;
      for (int d = 0; d < dim; ++d) partial *= (d == g) ? derivative[d] : factor[d];
      (*gradient)[g] = partial;
    }
  return value;
}

template <int dim> void check_partition_of_unity(int order) {
  VectorX values;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients;
  for (const Point<dim>& xi : sample_points<dim>()) {
    fem::tabulate_shape<dim>(order, xi, values, gradients);
    ASSERT_EQ(values.size(), n_nodes<dim>(order));
    ASSERT_EQ(gradients.cols(), n_nodes<dim>(order));
    EXPECT_TRUE(approx(values.sum(), 1.0, 0.0, lagrange_roundoff));
    // The gradient of Σ N_a = 1 vanishes; entries are O(1), so round-off again.
    for (int d = 0; d < dim; ++d) EXPECT_TRUE(approx(gradients.row(d).sum(), 0.0, 0.0, 1e-13));
  }
}

TEST(Lagrange, PartitionOfUnityAndZeroGradientSum) {
  check_partition_of_unity<2>(1);
  check_partition_of_unity<2>(2);
  check_partition_of_unity<3>(1);
  check_partition_of_unity<3>(2);
}

template <int dim> void check_kronecker_delta(int order) {
  VectorX values;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients;
  for (int a = 0; a < n_nodes<dim>(order); ++a) {
    fem::tabulate_shape<dim>(order, fem::reference_node<dim>(order, a), values, gradients);
    for (int b = 0; b < n_nodes<dim>(order); ++b)
      // The node coordinates −1, 0, 1 are exact, so N_b(ξ_a) is exactly 0 or 1
      // up to the last bit.
      EXPECT_TRUE(approx(values[b], a == b ? 1.0 : 0.0, 0.0, 1e-15))
          << "N_" << b << " at node " << a;
  }
}

TEST(Lagrange, KroneckerDeltaAtTheReferenceNodes) {
  check_kronecker_delta<2>(1);
  check_kronecker_delta<2>(2);
  check_kronecker_delta<3>(1);
  check_kronecker_delta<3>(2);
}

TEST(Lagrange, ReferenceNodesAreLexicographicWithXFastest) {
  // Drawing in fem/lagrange.hpp: Q1 0 (−1,−1), 1 (1,−1), 2 (−1,1), 3 (1,1);
  // Q2 4 is the centre, 5 the right mid-edge, 7 the top mid-edge.
  EXPECT_EQ(fem::reference_node<2>(1, 0), Point<2>(-1.0, -1.0));
  EXPECT_EQ(fem::reference_node<2>(1, 1), Point<2>(1.0, -1.0));
  EXPECT_EQ(fem::reference_node<2>(1, 2), Point<2>(-1.0, 1.0));
  EXPECT_EQ(fem::reference_node<2>(1, 3), Point<2>(1.0, 1.0));
  EXPECT_EQ(fem::reference_node<2>(2, 1), Point<2>(0.0, -1.0));
  EXPECT_EQ(fem::reference_node<2>(2, 4), Point<2>(0.0, 0.0));
  EXPECT_EQ(fem::reference_node<2>(2, 5), Point<2>(1.0, 0.0));
  EXPECT_EQ(fem::reference_node<2>(2, 7), Point<2>(0.0, 1.0));
  EXPECT_EQ(fem::reference_node<3>(1, 5), Point<3>(1.0, -1.0, 1.0)); // 5 = 1 + 0·2 + 1·4
  EXPECT_EQ(fem::reference_node<3>(2, 13), Point<3>(0.0, 0.0, 0.0)); // 13 = 1 + 1·3 + 1·9
  EXPECT_EQ(fem::reference_node<3>(2, 26), Point<3>(1.0, 1.0, 1.0));
  EXPECT_EQ(fem::reference_node<3>(2, 11), Point<3>(1.0, -1.0, 0.0)); // 11 = 2 + 0·3 + 1·9
  EXPECT_EQ(fem::lattice_coordinate(2, 1), 0.0);
  EXPECT_EQ(fem::element_order(fem::ElementKind::Q1), 1);
  EXPECT_EQ(fem::element_order(fem::ElementKind::Q2), 2);
  EXPECT_EQ(fem::element_name(fem::ElementKind::Q2), "Q2");
}

template <int dim> void check_gradients_against_finite_differences(int order) {
  // Each N_a is a polynomial of degree ≤ 2 in every single variable, so the
  // central difference has no truncation error; what is left is round-off
  // ≈ ε·|N|/h ≈ 1e-16·1.2/1e-6 ≈ 1e-10. 1e-8 absolute leaves margin and is
  // still 5 orders below an O(0.5) derivative.
  const double h = 1e-6;
  VectorX values, plus, minus;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients, unused;
  for (const Point<dim>& xi : sample_points<dim>()) {
    fem::tabulate_shape<dim>(order, xi, values, gradients);
    for (int g = 0; g < dim; ++g) {
      Point<dim> forward = xi, backward = xi;
      forward[g] += h;
      backward[g] -= h;
      fem::tabulate_shape<dim>(order, forward, plus, unused);
      fem::tabulate_shape<dim>(order, backward, minus, unused);
      for (int a = 0; a < values.size(); ++a)
        EXPECT_TRUE(approx(gradients(g, a), (plus[a] - minus[a]) / (2 * h), 0.0, 1e-8))
            << "order " << order << ", dN_" << a << "/dxi_" << g;
    }
  }
}

TEST(Lagrange, GradientsMatchCentralFiniteDifferences) {
  check_gradients_against_finite_differences<2>(1);
  check_gradients_against_finite_differences<2>(2);
  check_gradients_against_finite_differences<3>(1);
  check_gradients_against_finite_differences<3>(2);
}

template <int dim> void check_hessians_against_finite_differences(int order) {
  // The gradients are exact polynomials of degree ≤ 2 per variable: their central
  // difference has no truncation error, only round-off ε/h ≈ 1e-11.
  const Real h = 1e-5;
  VectorX unused;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> plus, minus;
  for (const Point<dim>& xi : sample_points<dim>()) {
    const auto hessians = fem::tabulate_hessians<dim>(order, xi);
    for (int g = 0; g < dim; ++g) {
      Point<dim> forward = xi, backward = xi;
      forward[g] += h;
      backward[g] -= h;
      fem::tabulate_shape<dim>(order, forward, unused, plus);
      fem::tabulate_shape<dim>(order, backward, unused, minus);
      for (int a = 0; a < static_cast<int>(hessians.size()); ++a)
        for (int k = 0; k < dim; ++k) {
          EXPECT_TRUE(approx(hessians[a](k, g), (plus(k, a) - minus(k, a)) / (2 * h), 0.0, 1e-8))
              << "order " << order << ", d2N_" << a << "/dxi_" << k << "dxi_" << g;
          EXPECT_EQ(hessians[a](k, g), hessians[a](g, k));
        }
    }
  }
}

TEST(Lagrange, HessiansMatchCentralDifferencesOfTheGradients) {
  check_hessians_against_finite_differences<2>(1);
  check_hessians_against_finite_differences<2>(2);
  check_hessians_against_finite_differences<3>(1);
  check_hessians_against_finite_differences<3>(2);
}

template <int dim> void check_polynomial_reproduction(int order) {
  // Interpolating a polynomial of degree `order` per variable through the
  // nodes reproduces it and its gradient everywhere (Q_order completeness).
  const int n = n_nodes<dim>(order);
  VectorX nodal(n);
  for (int a = 0; a < n; ++a)
    nodal[a] = test_polynomial<dim>(order, fem::reference_node<dim>(order, a));
  VectorX values;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients;
  for (const Point<dim>& xi : sample_points<dim>()) {
    fem::tabulate_shape<dim>(order, xi, values, gradients);
    Point<dim> exact_gradient;
    const double exact = test_polynomial<dim>(order, xi, &exact_gradient);
    // Sums of ≤ 27 products of O(1) numbers: round-off.
    EXPECT_TRUE(approx(values.dot(nodal), exact, 1e-13, 1e-13));
    const Point<dim> gradient = gradients * nodal;
    for (int d = 0; d < dim; ++d) EXPECT_TRUE(approx(gradient[d], exact_gradient[d], 1e-13, 1e-13));
  }
}

TEST(Lagrange, ReproducesPolynomialsOfItsOrderAndTheirGradients) {
  check_polynomial_reproduction<2>(1);
  check_polynomial_reproduction<2>(2);
  check_polynomial_reproduction<3>(1);
  check_polynomial_reproduction<3>(2);
}

TEST(Lagrange, Q1DoesNotReproduceAQuadratic) {
  // Guard for the reproduction test: interpolating x² with Q1 must fail at the centre.
  VectorX values;
  Eigen::Matrix<Real, 2, Eigen::Dynamic> gradients;
  fem::tabulate_shape<2>(1, Point<2>(0.0, 0.0), values, gradients);
  double interpolated = 0.0;
  for (int a = 0; a < 4; ++a)
    interpolated += values[a] * std::pow(fem::reference_node<2>(1, a).x(), 2);
  EXPECT_TRUE(approx(interpolated, 1.0, 0.0, 1e-15)); // the chord, not x²(0) = 0
}

template <int dim> void check_gauss_to_nodes(int order, int n_points) {
  // A polynomial of degree ≤ n−1 per direction is determined by its values at
  // the n^dim Gauss points, so the extrapolation must return its nodal values.
  const fem::QuadratureRule<dim> rule = fem::gauss_rule<dim>(n_points);
  const MatrixX extrapolation = fem::gauss_to_nodes<dim>(order, n_points);
  ASSERT_EQ(extrapolation.rows(), n_nodes<dim>(order));
  ASSERT_EQ(extrapolation.cols(), rule.size());
  const double c[5] = {0.9, -0.4, 0.7, 0.3, -0.5};
  auto f = [&](const Point<dim>& x) {
    double value = 1.0;
    for (int d = 0; d < dim; ++d) {
      double factor = 0.0, power = 1.0; // Σ_k c_{k+d} x^k, k ≤ n−1
      for (int k = 0; k < n_points; ++k, power *= x[d]) factor += c[(k + d) % 5] * power;
      value *= factor;
    }
    return value;
  };
  VectorX samples(rule.size());
  for (int q = 0; q < rule.size(); ++q) samples[q] = f(rule.points[q]);
  const VectorX at_nodes = extrapolation * samples;
  for (int a = 0; a < n_nodes<dim>(order); ++a)
    // Extrapolating to ±1 amplifies round-off by the Lebesgue-like sum of
    // |ℓ_k(±1)| (≲ 10 in 3D for n = 4): 1e-12 is still round-off.
    EXPECT_TRUE(approx(at_nodes[a], f(fem::reference_node<dim>(order, a)), 1e-12, 1e-12))
        << "order " << order << ", " << n_points << " points, node " << a;
}

TEST(GaussToNodes, ReproducesPolynomialsOfDegreeBelowThePointCount) {
  for (int n = 1; n <= 4; ++n) {
    check_gauss_to_nodes<2>(1, n);
    check_gauss_to_nodes<2>(2, n);
    check_gauss_to_nodes<3>(1, n);
    check_gauss_to_nodes<3>(2, n);
  }
  check_gauss_to_nodes<2>(2, 5);
}

TEST(GaussToNodes, OnePointGivesTheCellValueAtEveryNode) {
  const MatrixX extrapolation = fem::gauss_to_nodes<2>(2, 1);
  ASSERT_EQ(extrapolation.cols(), 1);
  for (int a = 0; a < 9; ++a) EXPECT_EQ(extrapolation(a, 0), 1.0);
}

TEST(GaussToNodes, TwoPointsExtrapolateLinearlyToTheEnds) {
  // 1D by hand: Gauss points ±g, g = 1/√3; the node at +1 gets
  // ℓ_+(1) = (1 + g)/(2g) = (1 + √3)/2 and ℓ_−(1) = (1 − √3)/2.
  const MatrixX extrapolation = fem::gauss_to_nodes<1>(1, 2);
  const double s3 = std::sqrt(3.0);
  EXPECT_TRUE(approx(extrapolation(1, 1), (1 + s3) / 2, 1e-14));
  EXPECT_TRUE(approx(extrapolation(1, 0), (1 - s3) / 2, 1e-14));
  EXPECT_TRUE(approx(extrapolation(0, 0), (1 + s3) / 2, 1e-14));
}

} // namespace
} // namespace formflow::testing
