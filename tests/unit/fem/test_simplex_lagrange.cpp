// SPDX-License-Identifier: MIT
// P1, P2, P1b, P2+ shape functions on triangles and tetrahedra: nodal property, partition
// of unity, FD-checked gradients and Hessians, reproduced polynomials and bubbles, the
// extrapolation from quadrature points to nodes.
#include "formflow/fem/simplex_lagrange.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/simplex_quadrature.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace formflow::testing {
namespace {

struct SimplexLayoutCase {
  int order;
  bool bubbles;
};
constexpr SimplexLayoutCase simplex_layout_cases[] = {{1, false}, {2, false}, {1, true}, {2, true}};

const char* simplex_layout_name(int order, bool bubbles) {
  return order == 1 ? (bubbles ? "P1b" : "P1") : (bubbles ? "P2+" : "P2");
}

// Error budget of the shape functions. The primal functions (λ_i, λ(2λ − 1), 4λiλj and the
// bubbles scaled to 1 at their centroid) lie in [−1/8, 1] on the simplex. Their Vandermonde
// V at the nodes is the identity for P1/P2 and, for the bubble layouts, I + L with L
// strictly block-lower-triangular (the P1/P2 functions at the centroids: −1/9, −1/8, 1/4,
// 4/9, 27/64), so V⁻¹ = I − L + L² has entries ≤ 2 and N_a = Σ_b φ_b (V⁻¹)_ba (≤ 15 terms)
// is bounded by 30. Each term carries a few ulps: |δN| ≤ 15·2·4u ≈ 1.3e-14, and the LU
// inverse of this well-conditioned V adds about as much: 1e-13 is round-off.
constexpr double simplex_shape_roundoff = 1e-13;
// The largest |N_a| the budget above allows, for the finite-difference round-off.
constexpr double simplex_shape_bound = 30;

/// Reproducible interior points of the unit simplex, with the centroid and points near a
/// vertex and near an edge.
template <int dim> std::vector<Point<dim>> simplex_sample_points() {
  std::mt19937 generator(20250311);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Point<dim>> points;
  while (points.size() < 12) {
    Point<dim> xi;
    for (int d = 0; d < dim; ++d) xi[d] = uniform(generator);
    if (xi.sum() < 1) points.push_back(xi);
  }
  points.push_back(Point<dim>::Constant(1.0 / (dim + 1)));
  Point<dim> near_vertex = Point<dim>::Constant(0.01);
  near_vertex[0] = 0.97;
  points.push_back(near_vertex);
  Point<dim> near_edge = Point<dim>::Zero();
  near_edge[0] = 0.5;
  near_edge[dim - 1] += 0.499;
  points.push_back(near_edge);
  return points;
}

template <int dim> std::array<double, dim + 1> simplex_barycentrics(const Point<dim>& xi) {
  std::array<double, dim + 1> lambda{};
  lambda[0] = 1 - xi.sum();
  for (int d = 0; d < dim; ++d) lambda[d + 1] = xi[d];
  return lambda;
}

/// A complete polynomial of degree `order` (1 or 2) with all terms present, and its gradient.
template <int dim>
double simplex_test_polynomial(int order, const Point<dim>& x, Point<dim>* gradient = nullptr) {
  // p = 0.3 + Σ c_d x_d + [order 2] Σ_{d ≤ e} c_de x_d x_e.
  const double linear[3] = {0.8, -1.1, 0.6};
  const double quadratic[3][3] = {{-0.7, 0.4, 1.2}, {0, 0.9, -0.5}, {0, 0, -1.3}};
  double value = 0.3;
  Point<dim> g;
  for (int d = 0; d < dim; ++d) {
    value += linear[d] * x[d];
    g[d] = linear[d];
  }
  if (order >= 2)
    for (int d = 0; d < dim; ++d)
      for (int e = d; e < dim; ++e) {
        value += quadratic[d][e] * x[d] * x[e];
        g[d] += quadratic[d][e] * x[e];
        g[e] += quadratic[d][e] * x[d];
      }
  if (gradient) *gradient = g;
  return value;
}

template <int dim> void check_simplex_node_count_and_kronecker(int order, bool bubbles) {
  const int n = fem::simplex_nodes<dim>(order, bubbles);
  const int p_dimension = order == 1 ? dim + 1 : (dim + 1) * (dim + 2) / 2;
  const int extra = !bubbles ? 0 : (dim == 3 && order == 2 ? 5 : 1);
  ASSERT_EQ(n, p_dimension + extra);
  VectorX values;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients;
  for (int a = 0; a < n; ++a) {
    fem::tabulate_simplex_shape<dim>(
        order, bubbles, fem::simplex_reference_node<dim>(order, bubbles, a), values, gradients);
    ASSERT_EQ(values.size(), n);
    ASSERT_EQ(gradients.cols(), n);
    for (int b = 0; b < n; ++b)
      EXPECT_TRUE(approx(values[b], a == b ? 1.0 : 0.0, 0.0, simplex_shape_roundoff))
          << "dim " << dim << ", " << simplex_layout_name(order, bubbles) << ": N_" << b
          << " at node " << a;
  }
}

TEST(SimplexLagrange, NodeCountsAndKroneckerDeltaAtTheNodes) {
  for (const auto& c : simplex_layout_cases) {
    check_simplex_node_count_and_kronecker<2>(c.order, c.bubbles);
    check_simplex_node_count_and_kronecker<3>(c.order, c.bubbles);
  }
}

TEST(SimplexLagrange, NodesFollowVtkOrder) {
  // The drawing in fem/simplex_lagrange.hpp.
  using P2 = Point<2>;
  using P3 = Point<3>;
  EXPECT_EQ(fem::simplex_nodes<2>(1, false), 3);
  EXPECT_EQ(fem::simplex_nodes<2>(2, false), 6);
  EXPECT_EQ(fem::simplex_nodes<2>(1, true), 4);
  EXPECT_EQ(fem::simplex_nodes<2>(2, true), 7);
  EXPECT_EQ(fem::simplex_nodes<3>(1, false), 4);
  EXPECT_EQ(fem::simplex_nodes<3>(2, false), 10);
  EXPECT_EQ(fem::simplex_nodes<3>(1, true), 5);
  EXPECT_EQ(fem::simplex_nodes<3>(2, true), 15);
  EXPECT_EQ(fem::simplex_reference_node<2>(2, false, 0), P2(0, 0));
  EXPECT_EQ(fem::simplex_reference_node<2>(2, false, 1), P2(1, 0));
  EXPECT_EQ(fem::simplex_reference_node<2>(2, false, 2), P2(0, 1));
  EXPECT_EQ(fem::simplex_reference_node<2>(2, false, 3), P2(0.5, 0));
  EXPECT_EQ(fem::simplex_reference_node<2>(2, false, 4), P2(0.5, 0.5));
  EXPECT_EQ(fem::simplex_reference_node<2>(2, false, 5), P2(0, 0.5));
  EXPECT_EQ(fem::simplex_reference_node<2>(1, true, 3), P2(1.0 / 3, 1.0 / 3));
  EXPECT_EQ(fem::simplex_reference_node<2>(2, true, 6), P2(1.0 / 3, 1.0 / 3));
  EXPECT_EQ(fem::simplex_reference_node<3>(1, false, 3), P3(0, 0, 1));
  EXPECT_EQ(fem::simplex_reference_node<3>(2, false, 4), P3(0.5, 0, 0));   // (0, 1)
  EXPECT_EQ(fem::simplex_reference_node<3>(2, false, 5), P3(0.5, 0.5, 0)); // (1, 2)
  EXPECT_EQ(fem::simplex_reference_node<3>(2, false, 6), P3(0, 0.5, 0));   // (2, 0)
  EXPECT_EQ(fem::simplex_reference_node<3>(2, false, 7), P3(0, 0, 0.5));   // (0, 3)
  EXPECT_EQ(fem::simplex_reference_node<3>(2, false, 8), P3(0.5, 0, 0.5)); // (1, 3)
  EXPECT_EQ(fem::simplex_reference_node<3>(2, false, 9), P3(0, 0.5, 0.5)); // (2, 3)
  EXPECT_EQ(fem::simplex_reference_node<3>(1, true, 4), P3(0.25, 0.25, 0.25));
  const double t = 1.0 / 3;
  EXPECT_EQ(fem::simplex_reference_node<3>(2, true, 10), P3(t, t, t)); // opposite v0
  EXPECT_EQ(fem::simplex_reference_node<3>(2, true, 11), P3(0, t, t)); // opposite v1
  EXPECT_EQ(fem::simplex_reference_node<3>(2, true, 12), P3(t, 0, t)); // opposite v2
  EXPECT_EQ(fem::simplex_reference_node<3>(2, true, 13), P3(t, t, 0)); // opposite v3
  EXPECT_EQ(fem::simplex_reference_node<3>(2, true, 14), P3(0.25, 0.25, 0.25));
}

template <int dim> void check_simplex_partition_of_unity(int order, bool bubbles) {
  VectorX values;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients;
  for (const Point<dim>& xi : simplex_sample_points<dim>()) {
    fem::tabulate_simplex_shape<dim>(order, bubbles, xi, values, gradients);
    EXPECT_TRUE(approx(values.sum(), 1.0, 0.0, simplex_shape_roundoff));
    // Gradients of the primal functions are ≤ 20 (the cell bubble's λ-derivative is at
    // most 256/27 ≈ 9.5, twice that through λ0): ten times the value budget.
    for (int d = 0; d < dim; ++d)
      EXPECT_TRUE(approx(gradients.row(d).sum(), 0.0, 0.0, 10 * simplex_shape_roundoff))
          << "dim " << dim << ", " << simplex_layout_name(order, bubbles);
  }
}

TEST(SimplexLagrange, PartitionOfUnityAndZeroGradientSum) {
  for (const auto& c : simplex_layout_cases) {
    check_simplex_partition_of_unity<2>(c.order, c.bubbles);
    check_simplex_partition_of_unity<3>(c.order, c.bubbles);
  }
}

template <int dim> void check_simplex_gradients_by_differences(int order, bool bubbles) {
  // Central difference error: truncation h²/6·|∂³N/∂ξ_g³| + round-off ≈ u·max|N|/h. Every
  // primal function is a product of barycentrics with each λ_i at most squared, and only
  // λ0 and λ_g depend on ξ_g, linearly, so N is at most quadratic in each single ξ_g: the
  // truncation term is zero. With h = 1e-3 the round-off is ≤ 1.1e-16·30/1e-3 ≈ 3.3e-12;
  // thirty times that, 1e-10, is still far below the h²/6 ≈ 2e-7 a cubic term would leave.
  const double h = 1e-3;
  const double tolerance = 30 * (1.1e-16 * simplex_shape_bound / h); // margin 30
  VectorX values, plus, minus;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients, unused;
  for (const Point<dim>& xi : simplex_sample_points<dim>()) {
    fem::tabulate_simplex_shape<dim>(order, bubbles, xi, values, gradients);
    for (int g = 0; g < dim; ++g) {
      Point<dim> forward = xi, backward = xi;
      forward[g] += h;
      backward[g] -= h;
      fem::tabulate_simplex_shape<dim>(order, bubbles, forward, plus, unused);
      fem::tabulate_simplex_shape<dim>(order, bubbles, backward, minus, unused);
      for (int a = 0; a < values.size(); ++a)
        EXPECT_TRUE(approx(gradients(g, a), (plus[a] - minus[a]) / (2 * h), 0.0, tolerance))
            << "dim " << dim << ", " << simplex_layout_name(order, bubbles) << ", dN_" << a
            << "/dxi_" << g;
    }
  }
}

TEST(SimplexLagrange, GradientsMatchCentralFiniteDifferences) {
  for (const auto& c : simplex_layout_cases) {
    check_simplex_gradients_by_differences<2>(c.order, c.bubbles);
    check_simplex_gradients_by_differences<3>(c.order, c.bubbles);
  }
}

template <int dim> void check_simplex_hessians_by_differences(int order, bool bubbles) {
  // The gradients are, like N, at most quadratic in each single ξ_g (differentiating does
  // not raise the degree in ξ_g): no truncation error. Round-off u·max|∇N|/h, with
  // |∇N| ≤ 20 (primal gradients) · 30 (Σ|V⁻¹|) = 600 and h = 1e-3: ≈ 6.6e-11.
  const Real h = 1e-3;
  const double tolerance = 600 * 1.1e-16 / h * 10; // ten times the estimate above
  VectorX unused;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> plus, minus;
  for (const Point<dim>& xi : simplex_sample_points<dim>()) {
    const auto hessians = fem::tabulate_simplex_hessians<dim>(order, bubbles, xi);
    ASSERT_EQ(static_cast<int>(hessians.size()), fem::simplex_nodes<dim>(order, bubbles));
    for (int g = 0; g < dim; ++g) {
      Point<dim> forward = xi, backward = xi;
      forward[g] += h;
      backward[g] -= h;
      fem::tabulate_simplex_shape<dim>(order, bubbles, forward, unused, plus);
      fem::tabulate_simplex_shape<dim>(order, bubbles, backward, unused, minus);
      for (int a = 0; a < static_cast<int>(hessians.size()); ++a)
        for (int k = 0; k < dim; ++k) {
          EXPECT_TRUE(
              approx(hessians[a](k, g), (plus(k, a) - minus(k, a)) / (2 * h), 0.0, tolerance))
              << "dim " << dim << ", " << simplex_layout_name(order, bubbles) << ", d2N_" << a
              << "/dxi_" << k << "dxi_" << g;
          // Both orders of differentiation are summed from the same products: a few ulps.
          EXPECT_TRUE(approx(hessians[a](k, g), hessians[a](g, k), 0.0, 1e-12));
        }
    }
  }
}

TEST(SimplexLagrange, HessiansMatchCentralDifferencesOfTheGradients) {
  for (const auto& c : simplex_layout_cases) {
    check_simplex_hessians_by_differences<2>(c.order, c.bubbles);
    check_simplex_hessians_by_differences<3>(c.order, c.bubbles);
  }
  // P1 has zero second derivatives, exactly (the primal λ_i are linear and V = I).
  for (const auto& hessian : fem::tabulate_simplex_hessians<3>(1, false, Point<3>(0.2, 0.3, 0.1)))
    EXPECT_TRUE(hessian.isZero(0.0));
}

/// Σ_a f(x_a) N_a(ξ) and its gradient reproduce f and ∇f at the sample points.
template <int dim, typename Function>
void check_simplex_reproduces(int order, bool bubbles, Function f, const char* what) {
  const int n = fem::simplex_nodes<dim>(order, bubbles);
  VectorX nodal(n);
  Point<dim> unused;
  for (int a = 0; a < n; ++a)
    nodal[a] = f(fem::simplex_reference_node<dim>(order, bubbles, a), unused);
  VectorX values;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients;
  for (const Point<dim>& xi : simplex_sample_points<dim>()) {
    fem::tabulate_simplex_shape<dim>(order, bubbles, xi, values, gradients);
    Point<dim> exact_gradient;
    const double exact = f(xi, exact_gradient);
    // |f| ≤ 3 at the nodes: ≤ 15 products with the shape budget, 3·15·30·4u ≈ 6e-13.
    EXPECT_TRUE(approx(values.dot(nodal), exact, 0.0, 1e-12))
        << "dim " << dim << ", " << simplex_layout_name(order, bubbles) << ", " << what;
    const Point<dim> gradient = gradients * nodal;
    for (int d = 0; d < dim; ++d) // the gradient budget is twenty times the value's
      EXPECT_TRUE(approx(gradient[d], exact_gradient[d], 0.0, 2e-11))
          << "dim " << dim << ", " << simplex_layout_name(order, bubbles) << ", " << what;
  }
}

template <int dim> void check_simplex_polynomial_reproduction(int order, bool bubbles) {
  for (int degree = 0; degree <= order; ++degree) // constants, P1 and (order 2) P2
    check_simplex_reproduces<dim>(
        order, bubbles,
        [degree](const Point<dim>& x, Point<dim>& gradient) {
          if (degree == 0) {
            gradient.setZero();
            return 0.3;
          }
          return simplex_test_polynomial<dim>(degree, x, &gradient);
        },
        "polynomial");
}

TEST(SimplexLagrange, ReproducesPolynomialsOfItsOrderAndTheirGradients) {
  for (const auto& c : simplex_layout_cases) {
    check_simplex_polynomial_reproduction<2>(c.order, c.bubbles);
    check_simplex_polynomial_reproduction<3>(c.order, c.bubbles);
  }
}

/// The bubble Π_{i in members} λ_i and its ξ-gradient.
template <int dim>
double simplex_bubble(const std::vector<int>& members, const Point<dim>& xi, Point<dim>& gradient) {
  const auto lambda = simplex_barycentrics<dim>(xi);
  double value = 1;
  for (int i : members) value *= lambda[i];
  gradient.setZero();
  for (int i : members) {
    double others = 1;
    for (int j : members)
      if (j != i) others *= lambda[j];
    if (i == 0)
      gradient -= Point<dim>::Constant(others); // ∂λ0/∂ξ_d = −1
    else
      gradient[i - 1] += others;
  }
  return value;
}

TEST(SimplexLagrange, BubbleLayoutsReproduceTheirBubbles) {
  const std::vector<int> triangle{0, 1, 2}, tetrahedron{0, 1, 2, 3};
  auto triangle_bubble = [&](const Point<2>& x, Point<2>& g) {
    return simplex_bubble<2>(triangle, x, g);
  };
  auto tetrahedron_bubble = [&](const Point<3>& x, Point<3>& g) {
    return simplex_bubble<3>(tetrahedron, x, g);
  };
  for (int order : {1, 2}) {
    check_simplex_reproduces<2>(order, true, triangle_bubble, "cell bubble");
    check_simplex_reproduces<3>(order, true, tetrahedron_bubble, "cell bubble");
  }
  for (int k = 0; k < 4; ++k) { // P2+: the face bubble of the face opposite vertex k
    std::vector<int> face;
    for (int i = 0; i < 4; ++i)
      if (i != k) face.push_back(i);
    check_simplex_reproduces<3>(
        2, true, [&](const Point<3>& x, Point<3>& g) { return simplex_bubble<3>(face, x, g); },
        "face bubble");
  }
}

TEST(SimplexLagrange, P1DoesNotReproduceAQuadraticNorP2TheCellBubble) {
  // Guards for the reproduction tests. Interpolating ξ² with P1 gives the chord ξ, 1/3 at
  // the centroid instead of 1/9; interpolating λ0λ1λ2 with P2 gives 0 (it vanishes at every
  // P2 node) instead of 1/27.
  const Point<2> centroid(1.0 / 3, 1.0 / 3);
  VectorX values;
  Eigen::Matrix<Real, 2, Eigen::Dynamic> gradients;
  fem::tabulate_simplex_shape<2>(1, false, centroid, values, gradients);
  double chord = 0;
  for (int a = 0; a < 3; ++a)
    chord += values[a] * std::pow(fem::simplex_reference_node<2>(1, false, a).x(), 2);
  EXPECT_TRUE(approx(chord, 1.0 / 3, 0.0, simplex_shape_roundoff));
  fem::tabulate_simplex_shape<2>(2, false, centroid, values, gradients);
  double bubble = 0;
  Point<2> unused;
  for (int a = 0; a < 6; ++a)
    bubble += values[a] *
              simplex_bubble<2>({0, 1, 2}, fem::simplex_reference_node<2>(2, false, a), unused);
  EXPECT_TRUE(approx(bubble, 0.0, 0.0, simplex_shape_roundoff));
}

TEST(SimplexLagrange, StraightSidedCellsMapAffinely) {
  // The isoparametric map Σ x_a N_a of a straight-sided cell, its bubble nodes at the
  // centroids (the affine images of the reference centroids), is the affine map A ξ + b:
  // P1 reproduction, componentwise.
  Eigen::Matrix3d map;
  map << 2.0, 0.3, -0.4, 0.1, 1.5, 0.2, -0.3, 0.6, 0.9;
  const Point<3> shift(1.0, -2.0, 0.5);
  for (const auto& c : simplex_layout_cases) {
    const int n = fem::simplex_nodes<3>(c.order, c.bubbles);
    VectorX values;
    Eigen::Matrix<Real, 3, Eigen::Dynamic> gradients;
    for (const Point<3>& xi : simplex_sample_points<3>()) {
      fem::tabulate_simplex_shape<3>(c.order, c.bubbles, xi, values, gradients);
      Point<3> x = Point<3>::Zero();
      Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
      for (int a = 0; a < n; ++a) {
        const Point<3> node = map * fem::simplex_reference_node<3>(c.order, c.bubbles, a) + shift;
        x += values[a] * node;
        jacobian += node * gradients.col(a).transpose();
      }
      // Node coordinates ≤ 5 in magnitude (|A x| ≤ 2.7, |b| ≤ 2): five times the budgets of
      // the reproduction test (1e-12 for values, 2e-11 for gradients).
      EXPECT_TRUE((x - (map * xi + shift)).isZero(5e-12))
          << simplex_layout_name(c.order, c.bubbles);
      EXPECT_TRUE((jacobian - map).isZero(1e-10)) << simplex_layout_name(c.order, c.bubbles);
    }
  }
}

template <int dim>
void check_simplex_points_to_nodes(int order, bool bubbles, const fem::QuadratureRule<dim>& rule) {
  const MatrixX extrapolation = fem::simplex_points_to_nodes<dim>(order, bubbles, rule);
  const int n = fem::simplex_nodes<dim>(order, bubbles);
  ASSERT_EQ(extrapolation.rows(), n);
  ASSERT_EQ(extrapolation.cols(), rule.size());
  VectorX samples(rule.size());
  for (int q = 0; q < rule.size(); ++q)
    samples[q] = simplex_test_polynomial<dim>(order, rule.points[q]);
  const VectorX at_nodes = extrapolation * samples;
  // Extrapolating amplifies the samples' round-off (a few ulps of |p| ≤ 3) by the row sums
  // Σ_q |M_aq|, checked below to stay under 50, and the QR's backward error by the
  // conditioning of the point matrix: 1e-12 is round-off.
  for (int a = 0; a < n; ++a) {
    EXPECT_LT(extrapolation.row(a).cwiseAbs().sum(), 50.0) << "row " << a;
    EXPECT_TRUE(approx(
        at_nodes[a],
        simplex_test_polynomial<dim>(order, fem::simplex_reference_node<dim>(order, bubbles, a)),
        0.0, 1e-12))
        << "dim " << dim << ", " << simplex_layout_name(order, bubbles) << ", " << rule.size()
        << " points, node " << a;
  }
}

TEST(SimplexPointsToNodes, ReproducesPolynomialsOfTheElementOrder) {
  for (const auto& c : simplex_layout_cases) {
    // The lowest rules that determine P_order (triangle 3 and 6 points, tetrahedron 4 and
    // 27), where the fit interpolates, and richer ones, where it is a true least-squares fit.
    for (int degree : {2 * c.order, 2 * c.order + 3}) {
      check_simplex_points_to_nodes<2>(c.order, c.bubbles, fem::simplex_rule<2>(degree));
      check_simplex_points_to_nodes<3>(c.order, c.bubbles, fem::simplex_rule<3>(degree));
    }
  }
}

TEST(SimplexPointsToNodes, ThreePointsInterpolateLinearly) {
  // Triangle P1 from the 3-point rule (1/6, 1/6), (2/3, 1/6), (1/6, 2/3): the fit
  // interpolates, and by hand v1 = (1, 0) = 5/3·(2/3, 1/6) − 1/3·(1/6, 1/6) − 1/3·(1/6, 2/3),
  // so node 1 takes the point values with those weights.
  const fem::QuadratureRule<2> rule = fem::simplex_rule<2>(2);
  const MatrixX extrapolation = fem::simplex_points_to_nodes<2>(1, false, rule);
  for (int q = 0; q < 3; ++q) {
    const double expected =
        rule.points[q].isApprox(Point<2>(2.0 / 3, 1.0 / 6)) ? 5.0 / 3 : -1.0 / 3;
    EXPECT_TRUE(approx(extrapolation(1, q), expected, 0.0, 1e-14)) << q;
  }
}

TEST(SimplexLagrange, PreconditionsAreChecked) {
#if !defined(NDEBUG) || defined(FORMFLOW_ENABLE_ASSERTS)
  VectorX values;
  Eigen::Matrix<Real, 2, Eigen::Dynamic> gradients;
  EXPECT_THROW(fem::tabulate_simplex_shape<2>(3, false, Point<2>(0.2, 0.2), values, gradients),
               InternalError);
  EXPECT_THROW(fem::simplex_nodes<3>(0, true), InternalError);
  EXPECT_THROW(fem::simplex_reference_node<2>(1, false, 3), InternalError);
  // One point cannot determine a linear fit; six points on one line cannot either.
  EXPECT_THROW(fem::simplex_points_to_nodes<2>(1, false, fem::simplex_rule<2>(1)), InternalError);
  fem::QuadratureRule<2> collinear;
  for (int q = 1; q <= 6; ++q) {
    collinear.points.push_back(Point<2>(0.1 * q, 0.1 * q));
    collinear.weights.push_back(1.0 / 12);
  }
  EXPECT_THROW(fem::simplex_points_to_nodes<2>(1, false, collinear), InternalError);
#else
  GTEST_SKIP() << "FF_ASSERT is compiled out in this build";
#endif
}

} // namespace
} // namespace formflow::testing
