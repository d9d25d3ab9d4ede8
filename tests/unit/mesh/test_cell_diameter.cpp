// SPDX-License-Identifier: MIT
// Cell diameters: the h of a mesh that no single mesh.size describes.
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/cell_diameter.hpp"
#include "formflow/mesh/channel_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace formflow::mesh {
namespace {

TEST(CellDiameter, UniformSquaresHaveTheDiagonal) {
  for (int order : {1, 2}) {
    const CellDiameterRange range = cell_diameter_range(make_channel_mesh({}, 0.5, order));
    EXPECT_NEAR(range.smallest, std::sqrt(2.0) * 0.5, 1e-14) << "Q" << order;
    EXPECT_NEAR(range.largest, std::sqrt(2.0) * 0.5, 1e-14) << "Q" << order;
  }
}

TEST(CellDiameter, RectanglesOfTwoSizes) {
  // Two cells: [0, 3] × [0, 4] (diameter 5) and [3, 4] × [0, 4] (√17).
  Mesh<2> mesh;
  mesh.order = 1;
  mesh.nodes.resize(2, 6);
  mesh.nodes << 0.0, 3.0, 4.0, 0.0, 3.0, 4.0, //
      0.0, 0.0, 0.0, 4.0, 4.0, 4.0;
  mesh.cells.resize(4, 2);
  mesh.cells << 0, 1, //
      1, 2,           //
      3, 4,           //
      4, 5;
  const CellDiameterRange range = cell_diameter_range(mesh);
  EXPECT_DOUBLE_EQ(range.smallest, std::sqrt(17.0));
  EXPECT_DOUBLE_EQ(range.largest, 5.0);
}

TEST(CellDiameter, DistortionSpreadsTheRange) {
  const Real h = 0.125, diagonal = std::sqrt(2.0) * h;
  const CellDiameterRange range = cell_diameter_range(
      make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), 8, 8, 2, {Distortion::Random, 0.2, 3}));
  EXPECT_LT(range.smallest, diagonal);
  EXPECT_GT(range.largest, diagonal);
  // Offsets of at most 0.2 h per coordinate move a node by ≤ 0.2·√2 h, so a
  // node-to-node distance changes by at most twice that.
  const Real bound = 2 * 0.2 * std::sqrt(2.0) * h;
  EXPECT_GT(range.smallest, diagonal - bound);
  EXPECT_LT(range.largest, diagonal + bound);
}

TEST(CellDiameter, NoCellsNoDiameter) {
  const CellDiameterRange range = cell_diameter_range(Mesh<2>{});
  EXPECT_EQ(range.smallest, 0.0);
  EXPECT_EQ(range.largest, 0.0);
}

} // namespace
} // namespace formflow::mesh
