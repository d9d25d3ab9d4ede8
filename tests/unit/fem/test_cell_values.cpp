// SPDX-License-Identifier: MIT
// Isoparametric mapping on distorted cells: areas, gradients, face measures and normals.
#include "formflow/fem/cell_values.hpp"

#include "formflow/fem/lagrange.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace formflow::testing {
namespace {

using Nodes2 = fem::CellValues<2>::Gradients;
using Nodes3 = fem::CellValues<3>::Gradients;

// Geometry of O(1) size, rules of ≤ 27 points: sums of a few dozen O(1)
// products carry ~1e-15 error. 1e-13 relative is round-off with margin.
constexpr double roundoff = 1e-13;

/// A non-affine quadrilateral (x3 ≠ x1 + x2 − x0), lexicographic corners.
Nodes2 distorted_q1() {
  Nodes2 nodes(2, 4);
  nodes << 0.0, 2.0, 0.3, 2.4, //
      0.0, 0.2, 1.5, 1.9;
  return nodes;
}

/// The corners in counter-clockwise order 0, 1, 3, 2.
std::array<Point<2>, 4> ccw_corners(const Nodes2& q1) {
  return {q1.col(0), q1.col(1), q1.col(3), q1.col(2)};
}

/// Shoelace area of a counter-clockwise polygon.
double shoelace(const std::array<Point<2>, 4>& p) {
  double twice = 0.0;
  for (int k = 0; k < 4; ++k)
    twice += p[k].x() * p[(k + 1) % 4].y() - p[(k + 1) % 4].x() * p[k].y();
  return 0.5 * twice;
}

/// Polygon centroid (standard formula, independent of any FE code).
Point<2> polygon_centroid(const std::array<Point<2>, 4>& p) {
  Point<2> sum = Point<2>::Zero();
  for (int k = 0; k < 4; ++k) {
    const Point<2>& a = p[k];
    const Point<2>& b = p[(k + 1) % 4];
    sum += (a + b) * (a.x() * b.y() - b.x() * a.y());
  }
  return sum / (6.0 * shoelace(p));
}

/// Q2 nodes placed by the bilinear map of `q1` (straight edges, mid-nodes at midpoints).
Nodes2 q2_from_bilinear(const Nodes2& q1) {
  Nodes2 nodes(2, 9);
  for (int a = 0; a < 9; ++a) {
    const Point<2> xi = fem::reference_node<2>(2, a);
    const double s = 0.5 * (1 + xi.x()), t = 0.5 * (1 + xi.y());
    nodes.col(a) = (1 - s) * (1 - t) * q1.col(0) + s * (1 - t) * q1.col(1) +
                   (1 - s) * t * q1.col(2) + s * t * q1.col(3);
  }
  return nodes;
}

/// Q2 with a displaced centre node: the map is no longer bilinear, but the
/// centre shape function vanishes on the boundary, so the region is unchanged.
Nodes2 distorted_q2() {
  Nodes2 nodes = q2_from_bilinear(distorted_q1());
  nodes.col(4) += Point<2>(0.12, -0.07);
  return nodes;
}

/// Bottom edge of the Q1 corners: length and outward unit normal.
constexpr double bulge = 0.15;
double bottom_length() {
  return (distorted_q1().col(1) - distorted_q1().col(0)).norm();
}
Point<2> bottom_outward_normal() {
  const Point<2> edge = distorted_q1().col(1) - distorted_q1().col(0);
  return Point<2>(edge.y(), -edge.x()) / edge.norm(); // right of a counter-clockwise edge
}

/// Q2 whose bottom edge bulges outward: its mid-edge node moves by `bulge`
/// along the outward normal, so the edge becomes the parabola
/// x(ξ) = chord(ξ) + bulge (1 − ξ²) n and the area grows by ∫ bulge (1 − ξ²) L/2 dξ = ⅔ bulge L.
Nodes2 curved_q2() {
  Nodes2 nodes = distorted_q2();
  nodes.col(1) += bulge * bottom_outward_normal();
  return nodes;
}

double curved_q2_area() {
  return shoelace(ccw_corners(distorted_q1())) + 2.0 / 3.0 * bulge * bottom_length();
}

/// Area as Σ JxW for a rule of n points per direction.
template <int dim>
double measure(int order, int n, const typename fem::CellValues<dim>::Gradients& nodes) {
  fem::CellValues<dim> values(order, fem::gauss_rule<dim>(n));
  EXPECT_TRUE(values.reinit(nodes));
  double total = 0.0;
  for (int q = 0; q < values.n_points(); ++q) total += values.JxW(q);
  return total;
}

TEST(CellValues, Q1AreaIsTheShoelaceAreaForEveryRule) {
  // det J of a bilinear map is affine in each of ξ, η: even one point integrates it.
  const double exact = shoelace(ccw_corners(distorted_q1()));
  for (int n = 1; n <= 3; ++n)
    EXPECT_TRUE(approx(measure<2>(1, n, distorted_q1()), exact, roundoff)) << n;
}

TEST(CellValues, Q2AreaWithDisplacedCentreNodeIsUnchanged) {
  // det J has degree ≤ 3 per variable here, so 2×2 and 3×3 are exact.
  const double exact = shoelace(ccw_corners(distorted_q1()));
  for (int n = 2; n <= 3; ++n)
    EXPECT_TRUE(approx(measure<2>(2, n, distorted_q2()), exact, roundoff)) << n;
}

TEST(CellValues, Q2AreaWithCurvedEdgeAddsTheParabolicSegment) {
  for (int n = 2; n <= 3; ++n)
    EXPECT_TRUE(approx(measure<2>(2, n, curved_q2()), curved_q2_area(), roundoff)) << n;
}

TEST(CellValues, Q1QuadraturePointsReproduceThePolygonCentroid) {
  // ∫ x dA / A: x·det J is of degree 2 per variable, exact with 2×2.
  fem::CellValues<2> values(1, fem::gauss_rule<2>(2));
  ASSERT_TRUE(values.reinit(distorted_q1()));
  Point<2> moment = Point<2>::Zero();
  double area = 0.0;
  for (int q = 0; q < values.n_points(); ++q) {
    moment += values.JxW(q) * values.point(q);
    area += values.JxW(q);
  }
  const Point<2> centroid = polygon_centroid(ccw_corners(distorted_q1()));
  EXPECT_TRUE(approx(moment.x() / area, centroid.x(), roundoff));
  EXPECT_TRUE(approx(moment.y() / area, centroid.y(), roundoff));
}

template <int dim>
void check_linear_field_gradient(int order, int n,
                                 const typename fem::CellValues<dim>::Gradients& nodes) {
  // f = 0.3 + c·x is in the span of every isoparametric element, so its
  // interpolant's gradient is c exactly at every point (round-off only).
  Point<dim> c;
  for (int d = 0; d < dim; ++d) c[d] = 0.7 - 1.3 * d + 0.4 * d * d;
  VectorX nodal(nodes.cols());
  for (int a = 0; a < nodes.cols(); ++a) nodal[a] = 0.3 + c.dot(nodes.col(a));
  fem::CellValues<dim> values(order, fem::gauss_rule<dim>(n));
  ASSERT_TRUE(values.reinit(nodes));
  for (int q = 0; q < values.n_points(); ++q) {
    const Point<dim> gradient = values.gradients(q) * nodal;
    for (int d = 0; d < dim; ++d) EXPECT_TRUE(approx(gradient[d], c[d], 1e-12, 1e-12)) << "q " << q;
    // Shape values and gradients are consistent: Σ ∇N_a = 0 on the physical cell too.
    for (int d = 0; d < dim; ++d)
      EXPECT_TRUE(approx(values.gradients(q).row(d).sum(), 0.0, 0.0, 1e-12));
    EXPECT_TRUE(approx(values.shape(q).sum(), 1.0, 0.0, 1e-14));
  }
}

TEST(CellValues, GradientOfALinearFieldIsExactOnDistortedCells) {
  check_linear_field_gradient<2>(1, 2, distorted_q1());
  check_linear_field_gradient<2>(2, 3, distorted_q2());
  check_linear_field_gradient<2>(2, 3, curved_q2());
}

TEST(CellValues, ClockwiseNodeOrderIsReportedAsInverted) {
  Nodes2 mirrored = distorted_q1();
  mirrored.col(0).swap(mirrored.col(1)); // reflecting the lexicographic order flips det J
  mirrored.col(2).swap(mirrored.col(3));
  fem::CellValues<2> values(1, fem::gauss_rule<2>(2));
  EXPECT_FALSE(values.reinit(mirrored));
  EXPECT_TRUE(values.reinit(distorted_q1()));
}

/// Unit square base, top surface z = 1 + 0.5x + 0.3xy (non-affine, lexicographic a + 2b + 4c).
Nodes3 sheared_hex() {
  Nodes3 nodes(3, 8);
  nodes << 0, 1, 0, 1, 0, 1, 0, 1, //
      0, 0, 1, 1, 0, 0, 1, 1,      //
      0, 0, 0, 0, 1, 1.5, 1, 1.8;
  return nodes;
}
// ∫∫ (1 + 0.5x + 0.3xy) dx dy over the unit square = 1 + 0.25 + 0.075.
constexpr double sheared_hex_volume = 1.325;

/// Q2 hexahedron: affine image x = Aξ + b with the centre node displaced
/// (its shape function vanishes on the boundary): volume 8 det A.
Nodes3 distorted_q2_hex() {
  Tensor2<3> a;
  a << 1.0, 0.2, 0.1, //
      0.1, 0.9, 0.2,  //
      0.0, 0.3, 1.1;
  Nodes3 nodes(3, 27);
  for (int k = 0; k < 27; ++k)
    nodes.col(k) = a * fem::reference_node<3>(2, k) + Point<3>(0.5, -0.2, 1.0);
  nodes.col(13) += Point<3>(0.05, -0.04, 0.06);
  return nodes;
}
// det A = 1·(0.99 − 0.06) − 0.2·(0.11 − 0) + 0.1·(0.03 − 0) = 0.911.
constexpr double distorted_q2_hex_volume = 8 * 0.911;

TEST(CellValues, HexahedronVolumes) {
  EXPECT_TRUE(approx(measure<3>(1, 2, sheared_hex()), sheared_hex_volume, roundoff));
  EXPECT_TRUE(approx(measure<3>(2, 3, distorted_q2_hex()), distorted_q2_hex_volume, roundoff));
}

TEST(CellValues, GradientOfALinearFieldIsExactOnHexahedra) {
  check_linear_field_gradient<3>(1, 2, sheared_hex());
  check_linear_field_gradient<3>(2, 3, distorted_q2_hex());
}

// ---- FacetValues ------------------------------------------------------------

/// Outward normal of the counter-clockwise edge P → Q.
Point<2> outward(const Point<2>& p, const Point<2>& q) {
  const Point<2> edge = q - p;
  return Point<2>(edge.y(), -edge.x()) / edge.norm();
}

struct Edge {
  int face, from, to; // local face, and its end corners in counter-clockwise order
};
// Q1 corners 0 (bottom-left), 1, 2, 3 (top-right); counter-clockwise 0→1→3→2→0.
constexpr std::array<Edge, 4> q1_edges = {{{2, 0, 1}, {1, 1, 3}, {3, 3, 2}, {0, 2, 0}}};

TEST(FacetValues, StraightFacesHaveTheirLengthAndTheOutwardNormal) {
  const Nodes2 nodes = distorted_q1();
  const Point<2> centroid = polygon_centroid(ccw_corners(nodes));
  fem::FacetValues<2> values(1, fem::gauss_rule<1>(2));
  for (const Edge& edge : q1_edges) {
    values.reinit(nodes, edge.face);
    const Point<2> p = nodes.col(edge.from), q = nodes.col(edge.to);
    const Point<2> expected_normal = outward(p, q);
    double length = 0.0;
    for (int k = 0; k < values.n_points(); ++k) {
      length += values.JxW(k);
      EXPECT_TRUE(approx(values.normal(k).norm(), 1.0, 1e-14));
      EXPECT_TRUE(approx(values.normal(k).x(), expected_normal.x(), 0.0, 1e-14)) << edge.face;
      EXPECT_TRUE(approx(values.normal(k).y(), expected_normal.y(), 0.0, 1e-14)) << edge.face;
      EXPECT_GT((values.point(k) - centroid).dot(values.normal(k)), 0.0) << "face " << edge.face;
      // The face point lies on the segment PQ: zero cross product, O(1) values.
      const Point<2> r = values.point(k) - p, s = q - p;
      EXPECT_TRUE(approx(r.x() * s.y() - r.y() * s.x(), 0.0, 0.0, 1e-14));
    }
    EXPECT_TRUE(approx(length, (q - p).norm(), roundoff)) << "face " << edge.face;
  }
}

TEST(FacetValues, Q2FaceWithSlidMidNodeStillHasItsLength) {
  // Moving the mid-edge node along a straight edge changes only the
  // parametrisation: |dx/dξ| = L/2 − 2sξ > 0 is linear, and the face rule
  // integrates it exactly.
  Nodes2 nodes = q2_from_bilinear(distorted_q1());
  const Point<2> p = nodes.col(0), q = nodes.col(2);
  nodes.col(1) += 0.1 * (nodes.col(2) - nodes.col(0));
  fem::FacetValues<2> values(2, fem::gauss_rule<1>(3));
  values.reinit(nodes, 2);
  double length = 0.0;
  for (int k = 0; k < values.n_points(); ++k) {
    length += values.JxW(k);
    EXPECT_TRUE(approx(values.normal(k).x(), outward(p, q).x(), 0.0, 1e-14));
    EXPECT_TRUE(approx(values.normal(k).y(), outward(p, q).y(), 0.0, 1e-14));
  }
  EXPECT_TRUE(approx(length, (q - p).norm(), roundoff));
}

template <int dim>
void check_divergence_theorem(int order, const typename fem::CellValues<dim>::Gradients& nodes,
                              double volume) {
  // ∮ n dΓ = 0 and ∮ x·n dΓ = dim·|Ω|. n·JxW is the cofactor of J applied to
  // the reference normal, a polynomial, so an order+1 rule is exact.
  fem::FacetValues<dim> values(order, fem::gauss_rule<dim - 1>(order + 1));
  Point<dim> normal_sum = Point<dim>::Zero();
  double flux = 0.0;
  for (int face = 0; face < 2 * dim; ++face) {
    values.reinit(nodes, face);
    for (int q = 0; q < values.n_points(); ++q) {
      EXPECT_TRUE(approx(values.normal(q).norm(), 1.0, 1e-14));
      normal_sum += values.JxW(q) * values.normal(q);
      flux += values.JxW(q) * values.point(q).dot(values.normal(q));
    }
  }
  for (int d = 0; d < dim; ++d) EXPECT_TRUE(approx(normal_sum[d], 0.0, 0.0, 1e-13));
  EXPECT_TRUE(approx(flux, dim * volume, roundoff));
}

TEST(FacetValues, DivergenceTheoremOnCurvedAndDistortedCells) {
  check_divergence_theorem<2>(1, distorted_q1(), shoelace(ccw_corners(distorted_q1())));
  check_divergence_theorem<2>(2, curved_q2(), curved_q2_area());
  check_divergence_theorem<3>(1, sheared_hex(), sheared_hex_volume);
  check_divergence_theorem<3>(2, distorted_q2_hex(), distorted_q2_hex_volume);
}

TEST(FacetValues, CurvedEdgeNormalIsPerpendicularToTheParabola) {
  // On the bulged bottom edge x(ξ) = chord(ξ) + bulge(1 − ξ²) n, the tangent is
  // (L/2) t − 2 bulge ξ n; at ξ = 0 (middle point of the 3-point rule) the
  // normal is the chord's.
  const Point<2> n = bottom_outward_normal();
  const Point<2> t(-n.y(), n.x());
  const double half_length = 0.5 * bottom_length();
  std::vector<Real> xi, unused;
  fem::gauss_1d(3, xi, unused);
  fem::FacetValues<2> values(2, fem::gauss_rule<1>(3));
  values.reinit(curved_q2(), 2);
  for (int q = 0; q < 3; ++q) {
    const Point<2> tangent = half_length * t - 2 * bulge * xi[q] * n;
    EXPECT_TRUE(approx(values.normal(q).dot(tangent), 0.0, 0.0, 1e-14)) << q;
    EXPECT_GT(values.normal(q).dot(n), 0.0) << "normal must point out of the cell";
    // Surface element |dx/dξ| times the weight.
    EXPECT_TRUE(approx(values.JxW(q), unused[q] * tangent.norm(), roundoff));
  }
  EXPECT_TRUE(approx(values.normal(1).x(), n.x(), 0.0, 1e-14));
  EXPECT_TRUE(approx(values.normal(1).y(), n.y(), 0.0, 1e-14));
}

TEST(FacetValues, HexahedronPlanarFacesByHand) {
  // Sheared hexahedron: x = 0 face is the unit square; y = 0 a trapezoid with
  // heights 1 and 1.5 (area 1.25); x = 1 a trapezoid with heights 1.5 and 1.8
  // (area 1.65); y = 1 heights 1 and 1.8 (area 1.4); bottom z = 0 unit square.
  struct Face {
    int face;
    double area;
    Point<3> normal;
  };
  const std::array<Face, 5> faces = {{{0, 1.0, Point<3>(-1.0, 0.0, 0.0)},
                                      {1, 1.65, Point<3>(1.0, 0.0, 0.0)},
                                      {2, 1.25, Point<3>(0.0, -1.0, 0.0)},
                                      {3, 1.4, Point<3>(0.0, 1.0, 0.0)},
                                      {4, 1.0, Point<3>(0.0, 0.0, -1.0)}}};
  fem::FacetValues<3> values(1, fem::gauss_rule<2>(2));
  for (const Face& face : faces) {
    values.reinit(sheared_hex(), face.face);
    double area = 0.0;
    for (int q = 0; q < values.n_points(); ++q) {
      area += values.JxW(q);
      for (int d = 0; d < 3; ++d)
        EXPECT_TRUE(approx(values.normal(q)[d], face.normal[d], 0.0, 1e-14)) << face.face;
    }
    EXPECT_TRUE(approx(area, face.area, roundoff)) << "face " << face.face;
  }
}

TEST(FacetValues, FaceShapeFunctionsVanishOffTheFace) {
  // On face 2 (η = −1) of a Q2 cell only nodes 0, 1, 2 carry weight.
  fem::FacetValues<2> values(2, fem::gauss_rule<1>(3));
  values.reinit(distorted_q2(), 2);
  for (int q = 0; q < values.n_points(); ++q) {
    for (int a = 3; a < 9; ++a) EXPECT_TRUE(approx(values.shape(q)[a], 0.0, 0.0, 1e-15)) << a;
    EXPECT_TRUE(approx(values.shape(q).head<3>().sum(), 1.0, 0.0, 1e-14));
  }
}

} // namespace
} // namespace formflow::testing
