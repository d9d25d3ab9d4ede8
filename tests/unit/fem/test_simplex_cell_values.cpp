// SPDX-License-Identifier: MIT
// Cell and face values of simplices: the divergence theorem on one straight-sided
// triangle and tetrahedron, for every layout, checks the cell map, the face embedding, the
// outward normals and the surface measure together.
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/reference_element.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

namespace formflow::testing {
namespace {

// Both sides are sums of at most 4 faces × 16 points (or 64 cell points) of products of
// values below 10 (the field on a cell within [0, 2.5]^dim) and weights summing to the
// measure (≤ 1): a few hundred roundings of at most 10 · 1.1e-16 each, ≤ 1e-13; 1e-12
// leaves a margin of ten. Only Eigen's fixed-size arithmetic is involved (no BLAS), so
// OPENBLAS_CORETYPE cannot change it.
constexpr double divergence_roundoff = 1e-12;

/// v(x) = (x², x y[, y z]) or in 2D (x², x y): quadratic, so every layout of order 2
/// reproduces it; order 1 gets the linear field (y, x[, x + z]) instead.
template <int dim> Point<dim> test_field(const Point<dim>& x, int order) {
  Point<dim> v;
  if (order == 2) {
    v[0] = x[0] * x[0];
    v[1] = x[0] * x[1];
    if constexpr (dim == 3) v[2] = x[1] * x[2];
  } else {
    v[0] = x[1];
    v[1] = x[0];
    if constexpr (dim == 3) v[2] = x[0] + x[2];
  }
  return v;
}

template <int dim> void check_divergence_theorem(int order, bool bubbles) {
  const mesh::CellType type{mesh::CellShape::Simplex, order, bubbles};
  // A tilted, stretched simplex: x = A ξ + b.
  Tensor2<dim> a = Tensor2<dim>::Identity();
  a(0, 0) = 1.7;
  a(1, 0) = 0.4;
  a(0, 1) = -0.3;
  if constexpr (dim == 3) a(2, 1) = 0.5, a(0, 2) = 0.2, a(2, 2) = 1.3;
  const Point<dim> shift = Point<dim>::Constant(0.25);
  const int n = mesh::nodes_per_cell<dim>(type);
  typename fem::CellValues<dim>::Gradients nodes(dim, n), velocities(dim, n);
  for (int k = 0; k < n; ++k) {
    nodes.col(k) = a * fem::reference_node<dim>(type, k) + shift;
    velocities.col(k) = test_field<dim>(nodes.col(k), order);
  }
  fem::CellValues<dim> cell(type, fem::full_rule<dim>(type));
  ASSERT_TRUE(cell.reinit(nodes));
  Real volume_integral = 0.0;
  for (int q = 0; q < cell.n_points(); ++q)
    volume_integral += (velocities * cell.gradients(q).transpose()).trace() * cell.JxW(q);
  fem::FacetValues<dim> face(type, fem::face_rule<dim>(type));
  Real surface_integral = 0.0;
  for (int f = 0; f < mesh::faces_per_cell<dim>(type); ++f) {
    face.reinit(nodes, f);
    for (int q = 0; q < face.n_points(); ++q) {
      // Outward: the normal points away from the cell's centroid.
      const Point<dim> centroid = nodes.leftCols(dim + 1).rowwise().mean();
      EXPECT_GT(face.normal(q).dot(face.point(q) - centroid), 0.0) << "face " << f;
      surface_integral += (velocities * face.shape(q)).dot(face.normal(q)) * face.JxW(q);
    }
  }
  EXPECT_TRUE(approx(surface_integral, volume_integral, 0.0, divergence_roundoff))
      << "dim " << dim << " order " << order << " bubbles " << bubbles;
  // The volume itself: |det A| / dim!.
  Real measure = 0.0;
  for (int q = 0; q < cell.n_points(); ++q) measure += cell.JxW(q);
  EXPECT_TRUE(approx(measure, a.determinant() / (dim == 2 ? 2.0 : 6.0), divergence_roundoff));
}

TEST(SimplexCellValues, TrianglesHoldTheDivergenceTheorem) {
  for (int order : {1, 2})
    for (bool bubbles : {false, true}) check_divergence_theorem<2>(order, bubbles);
}

TEST(SimplexCellValues, TetrahedraHoldTheDivergenceTheorem) {
  for (int order : {1, 2})
    for (bool bubbles : {false, true}) check_divergence_theorem<3>(order, bubbles);
}

} // namespace
} // namespace formflow::testing
