// SPDX-License-Identifier: MIT
// Nodal interpolation between meshes (mesh sequencing's prolongation).
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/mesh/box_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace formflow {
namespace {

/// A vector field in the Q2 space of a bilinear cell (x², xy, y² are in it only on
/// affine cells; the box mesh's cells are rectangles): (x² − 2xy + 3, y² + x − y).
Point<2> quadratic_field(const Point<2>& x) {
  return Point<2>(x[0] * x[0] - 2.0 * x[0] * x[1] + 3.0, x[1] * x[1] + x[0] - x[1]);
}

VectorX nodal_values(const mesh::Mesh<2>& mesh, Point<2> (*field)(const Point<2>&)) {
  VectorX values(2 * mesh.n_nodes());
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    values.segment<2>(2 * node) = field(mesh.nodes.col(node));
  return values;
}

TEST(NodalInterpolation, ProlongsAQ2FieldExactlyToTheRefinedMesh) {
  const Point<2> lower(0.0, 0.0), upper(3.0, 2.0);
  const mesh::Mesh<2> coarse = mesh::make_box_mesh(lower, upper, 3, 2, 2);
  const mesh::Mesh<2> fine = mesh::make_box_mesh(lower, upper, 6, 4, 2);
  const VectorX prolonged =
      fem::interpolate_nodal_field(coarse, nodal_values(coarse, quadratic_field), 2, fine);
  EXPECT_LT((prolonged - nodal_values(fine, quadratic_field)).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(NodalInterpolation, NonNestedMeshesReproduceTheFieldToInterpolationError) {
  // 3 × 2 cells against 5 × 3 (not nested): a Q2 field is still reproduced
  // exactly, a smooth non-polynomial one to the coarse mesh's interpolation error.
  const Point<2> lower(0.0, 0.0), upper(3.0, 2.0);
  const mesh::Mesh<2> coarse = mesh::make_box_mesh(lower, upper, 3, 2, 2);
  const mesh::Mesh<2> other = mesh::make_box_mesh(lower, upper, 5, 3, 2);
  const VectorX exact =
      fem::interpolate_nodal_field(coarse, nodal_values(coarse, quadratic_field), 2, other);
  EXPECT_LT((exact - nodal_values(other, quadratic_field)).lpNorm<Eigen::Infinity>(), 1e-12);

  auto smooth = [](const Point<2>& x) { return Point<2>(std::sin(x[0]), std::cos(x[1])); };
  const VectorX interpolated =
      fem::interpolate_nodal_field(coarse, nodal_values(coarse, +smooth), 2, other);
  const Real error = (interpolated - nodal_values(other, +smooth)).lpNorm<Eigen::Infinity>();
  EXPECT_GT(error, 1e-6); // not nested: the fine nodes are not coarse nodes
  EXPECT_LT(error, 0.01); // Q2 on cells of size 1: h³/… ≈ 1e-2 at most
}

TEST(NodalInterpolation, NodesOutsideTheSourceTakeTheNearestBoundaryValue) {
  // The target sticks out by 0.1 at x = 3 (a curved outline approximated
  // differently): those nodes take the value on the source's edge x = 3.
  const mesh::Mesh<2> source = mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(3.0, 2.0), 3, 2, 2);
  const mesh::Mesh<2> target = mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(3.1, 2.0), 4, 2, 2);
  const VectorX values =
      fem::interpolate_nodal_field(source, nodal_values(source, quadratic_field), 2, target);
  for (Index node = 0; node < target.n_nodes(); ++node) {
    Point<2> x = target.nodes.col(node);
    x[0] = std::min(x[0], 3.0);
    EXPECT_LT((values.segment<2>(2 * node) - quadratic_field(x)).norm(), 1e-10) << "node " << node;
  }
}

} // namespace
} // namespace formflow
