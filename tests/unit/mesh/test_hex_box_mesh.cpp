// SPDX-License-Identifier: MIT
// The structured hexahedral box: counts, lattice positions and the labelled faces.
#include "formflow/mesh/hex_box_mesh.hpp"

#include <gtest/gtest.h>

#include <map>

namespace formflow::testing {

namespace {

using mesh::BoundaryLabel;

class HexBoxMesh : public ::testing::TestWithParam<int> {};

TEST_P(HexBoxMesh, CountsAndFacesOnTheRightSides) {
  const int order = GetParam();
  const Point<3> lower(1.0, -1.0, 0.0), upper(4.0, 1.0, 0.5);
  const std::array<BoundaryLabel, 6> labels = {BoundaryLabel::Rear,      BoundaryLabel::Front,
                                               BoundaryLabel::Symmetry,  BoundaryLabel::FreeExit,
                                               BoundaryLabel::Container, BoundaryLabel::Die};
  const mesh::Mesh<3> box = mesh::make_hex_box_mesh(lower, upper, {3, 2, 1}, order, labels);
  EXPECT_EQ(box.order, order);
  EXPECT_EQ(box.n_cells(), 6);
  EXPECT_EQ(box.nodes_per_cell(), (order + 1) * (order + 1) * (order + 1));
  EXPECT_EQ(box.n_nodes(), (3 * order + 1) * (2 * order + 1) * (order + 1));
  // Faces per box side: the cells touching it.
  std::map<int, int> faces_per_side;
  for (const mesh::BoundaryFacet& facet : box.facets) {
    ++faces_per_side[facet.local_face];
    EXPECT_EQ(facet.label, labels[facet.local_face]);
    const int axis = facet.local_face / 2;
    const Real bound = facet.local_face % 2 == 0 ? lower[axis] : upper[axis];
    for (int local : mesh::face_local_nodes<3>(box.nodes_per_side(), facet.local_face))
      EXPECT_EQ(box.nodes(axis, box.cells(local, facet.cell)), bound)
          << "cell " << facet.cell << " face " << facet.local_face;
  }
  EXPECT_EQ(faces_per_side, (std::map<int, int>{{0, 2}, {1, 2}, {2, 3}, {3, 3}, {4, 6}, {5, 6}}));
  // Lexicographic cells: local node a = i + n(j + n k) sits at the lattice
  // (two roundings of coordinates ≤ 4 apart from the generator's: 1e-14 ≈ 20 ulps)
  // position (i, j, k)/order of the cell's lower corner plus its side.
  const Point<3> side((upper - lower).array() / Eigen::Array3d(3, 2, 1));
  const int n = order + 1;
  for (Index c = 0; c < box.n_cells(); ++c) {
    const Point<3> corner = box.nodes.col(box.cells(0, c));
    for (int a = 0; a < box.nodes_per_cell(); ++a) {
      const Eigen::Array3d at(a % n, (a / n) % n, a / (n * n));
      const Point<3> expected = corner.array() + side.array() * at / order;
      EXPECT_LT((box.nodes.col(box.cells(a, c)) - expected).norm(), 1e-14) << c << " " << a;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, HexBoxMesh, ::testing::Values(1, 2));

} // namespace

} // namespace formflow::testing
