// SPDX-License-Identifier: MIT
// A contour band's pieces merged into their outlines: shared edges cancel, the covered
// area is kept, and edges that do not match stay in closed rings.
#include "formflow/io/plot/polygon_outlines.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace formflow::testing {

namespace {

using io::plot::Pixel;
using Polygons = std::vector<std::vector<Pixel>>;

/// The unit square at (i, j), counter-clockwise, its points moved by `jitter` (below the
/// snap: two cells' copies of a shared point agree to round-off only).
std::vector<Pixel> square(double i, double j, double jitter = 0.0) {
  return {{i, j + jitter}, {i + 1 - jitter, j}, {i + 1, j + 1 + jitter}, {i + jitter, j + 1}};
}

double signed_area(const std::vector<Pixel>& ring) {
  double twice = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Pixel& a = ring[k];
    const Pixel& b = ring[(k + 1) % ring.size()];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * twice;
}

double total_area(const Polygons& polygons) {
  double sum = 0.0;
  for (const auto& polygon : polygons) sum += signed_area(polygon);
  return sum;
}

/// A ring's points: each a corner of the union's boundary (no interior point is left).
bool on_boundary_of_grid(const Pixel& at, int columns, int rows) {
  return at[0] == 0.0 || at[1] == 0.0 || at[0] == columns || at[1] == rows;
}

} // namespace

TEST(PolygonOutlines, AGridOfCellsBecomesItsOuterRing) {
  Polygons cells;
  const int columns = 3, rows = 2;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) cells.push_back(square(i, j));
  const Polygons rings = io::plot::merged_outlines(cells);
  ASSERT_EQ(rings.size(), 1u);
  // The boundary's 10 grid points, each once; the interior's 2 are gone.
  EXPECT_EQ(rings[0].size(), 2u * (columns + rows));
  for (const Pixel& at : rings[0]) EXPECT_TRUE(on_boundary_of_grid(at, columns, rows));
  EXPECT_DOUBLE_EQ(signed_area(rings[0]), columns * rows);
}

TEST(PolygonOutlines, PointsThatAgreeToRoundOffAreOnePoint) {
  // Each cell's copy of a shared point differs by 1e-9 px, far below the 1/1024 snap.
  Polygons cells;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) cells.push_back(square(i, j, (i + 2 * j) * 1e-9));
  const Polygons rings = io::plot::merged_outlines(cells);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0].size(), 8u);
  // The kept copies are within 3e-9 of the grid: the area within 4 edges' worth of it.
  EXPECT_NEAR(signed_area(rings[0]), 4.0, 8 * 2 * 3e-9);
}

TEST(PolygonOutlines, AHoleStaysAHoleAndApartCellsStayApart) {
  Polygons cells;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (i != 1 || j != 1) cells.push_back(square(i, j));
  cells.push_back(square(10, 10)); // apart
  const Polygons rings = io::plot::merged_outlines(cells);
  ASSERT_EQ(rings.size(), 3u);
  std::vector<double> areas;
  for (const auto& ring : rings) areas.push_back(signed_area(ring));
  std::sort(areas.begin(), areas.end());
  // The hole runs the other way round: filled with the nonzero rule it stays empty.
  EXPECT_DOUBLE_EQ(areas[0], -1.0);
  EXPECT_DOUBLE_EQ(areas[1], 1.0);
  EXPECT_DOUBLE_EQ(areas[2], 9.0);
}

TEST(PolygonOutlines, EdgesThatDoNotMatchStayInClosedRings) {
  // A cell beside two half-height cells: its right edge is one edge, theirs two, so
  // nothing cancels there (a T-junction); every ring is still closed and the covered
  // area is kept.
  const Polygons cells = {
      square(0, 0), {{1, 0}, {2, 0}, {2, 0.5}, {1, 0.5}}, {{1, 0.5}, {2, 0.5}, {2, 1}, {1, 1}}};
  const Polygons rings = io::plot::merged_outlines(cells);
  ASSERT_FALSE(rings.empty());
  EXPECT_DOUBLE_EQ(total_area(rings), total_area(cells));
  // The two half cells merged (their shared edge cancelled): 4 + 6 points.
  std::size_t points = 0;
  for (const auto& ring : rings) points += ring.size();
  EXPECT_EQ(points, 10u);
}

TEST(PolygonOutlines, DegenerateInputGivesNoRing) {
  const Polygons nothing = {{{0, 0}, {1, 1}}, {{2, 2}, {2, 2}, {2, 2}}};
  EXPECT_TRUE(io::plot::merged_outlines(nothing).empty());
  // A cell and its mirror image (opposite orientation) cancel completely.
  std::vector<Pixel> mirror = square(0, 0);
  std::reverse(mirror.begin(), mirror.end());
  const Polygons both = {square(0, 0), mirror};
  EXPECT_TRUE(io::plot::merged_outlines(both).empty());
}

} // namespace formflow::testing
