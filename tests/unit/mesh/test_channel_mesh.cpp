// SPDX-License-Identifier: MIT
// The structured channel mesh: counts by hand, cell orientation, boundary labels, face numbering.
#include "formflow/mesh/channel_mesh.hpp"

#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace formflow::testing {
namespace {

using mesh::BoundaryLabel;

// Coordinates of the generator are computed as length·i/n, so they carry at
// most a few ulps of O(10) values: 1e-12 absolute is round-off, far below any
// real misplacement (the smallest cell side is 0.5).
constexpr double coordinate_tol = 1e-12;

/// Local index of the lattice node (a, b) of a cell with `n_side` nodes per
/// direction: lexicographic, x fastest (fem/lagrange.hpp drawing).
int local_index(int n_side, int a, int b) {
  return b * n_side + a;
}

Point<2> node_of(const mesh::Mesh<2>& m, Index cell, int local) {
  return m.nodes.col(m.cells(local, cell));
}

/// Signed area of the cell's corner polygon, taken counter-clockwise through
/// the lexicographic corners 0, n−1, n²−1, n(n−1) (bottom-left, bottom-right,
/// top-right, top-left).
double corner_signed_area(const mesh::Mesh<2>& m, Index cell) {
  const int n = m.nodes_per_side();
  const std::array<int, 4> corners = {local_index(n, 0, 0), local_index(n, n - 1, 0),
                                      local_index(n, n - 1, n - 1), local_index(n, 0, n - 1)};
  double twice_area = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Point<2> p = node_of(m, cell, corners[k]);
    const Point<2> q = node_of(m, cell, corners[(k + 1) % 4]);
    twice_area += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice_area;
}

struct MeshCase {
  const char* name;
  double size;
  int order;
  Index cells;
  Index nodes;
};

// Counts by hand. Cells: container (10/s)², exit (10/s)·(5/s).
// Nodes: the container lattice has (o·10/s + 1)² points, the exit adds o·10/s
// columns (its first column is shared with the die face) of o·5/s + 1 points.
//   mesh I  (s = 10/6): 36 + 18 = 54 cells; Q1 7² + 6·4 = 73; Q2 13² + 12·7 = 253.
//   mesh II (s = 1):   100 + 50 = 150 cells; Q1 11² + 10·6 = 181; Q2 21² + 20·11 = 661.
const std::array<MeshCase, 4> benchmark_meshes = {{
    {"mesh_I_Q1", 10.0 / 6.0, 1, 54, 73},
    {"mesh_I_Q2", 10.0 / 6.0, 2, 54, 253},
    {"mesh_II_Q1", 1.0, 1, 150, 181},
    {"mesh_II_Q2", 1.0, 2, 150, 661},
}};

void PrintTo(const MeshCase& c, std::ostream* os) {
  *os << c.name;
}

class BenchmarkMesh : public ::testing::TestWithParam<MeshCase> {
protected:
  mesh::Mesh<2> make() const {
    return mesh::make_channel_mesh(mesh::ChannelGeometry{}, GetParam().size, GetParam().order);
  }
};

TEST_P(BenchmarkMesh, CellAndNodeCountsMatchHandCount) {
  const mesh::Mesh<2> m = make();
  EXPECT_EQ(m.order, GetParam().order);
  EXPECT_EQ(m.n_cells(), GetParam().cells);
  EXPECT_EQ(m.n_nodes(), GetParam().nodes);
  EXPECT_EQ(m.nodes_per_cell(), (GetParam().order + 1) * (GetParam().order + 1));
}

TEST_P(BenchmarkMesh, NodesAreDistinctAndAllUsed) {
  const mesh::Mesh<2> m = make();
  // Distinct positions (rounded far below the lattice spacing) mean no node is
  // duplicated, so neighbouring cells share their common nodes (conformity).
  std::set<std::pair<long long, long long>> positions;
  for (Index n = 0; n < m.n_nodes(); ++n)
    positions.insert({std::llround(m.nodes(0, n) * 1e6), std::llround(m.nodes(1, n) * 1e6)});
  EXPECT_EQ(static_cast<Index>(positions.size()), m.n_nodes());

  std::vector<bool> used(m.n_nodes(), false);
  for (Index c = 0; c < m.n_cells(); ++c)
    for (int a = 0; a < m.nodes_per_cell(); ++a) {
      const Index node = m.cells(a, c);
      ASSERT_GE(node, 0);
      ASSERT_LT(node, m.n_nodes());
      used[node] = true;
    }
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
}

TEST_P(BenchmarkMesh, EveryCellIsACounterClockwiseSquareOfTheRequestedSize) {
  const mesh::Mesh<2> m = make();
  const double size = GetParam().size;
  double total_area = 0.0;
  for (Index c = 0; c < m.n_cells(); ++c) {
    const double area = corner_signed_area(m, c);
    ASSERT_GT(area, 0.0) << "cell " << c << " is clockwise or degenerate";
    EXPECT_TRUE(approx(area, size * size, 1e-12, coordinate_tol)) << "cell " << c;
    total_area += area;
  }
  // Container 10×10 plus exit 10×5; round-off only (≤ 150 cells of O(1) area).
  EXPECT_TRUE(approx(total_area, 150.0, 1e-12));
}

TEST_P(BenchmarkMesh, CellNodesFollowTheLexicographicLattice) {
  const mesh::Mesh<2> m = make();
  const int order = m.order, n_side = m.nodes_per_side();
  const double spacing = GetParam().size / order;
  for (Index c = 0; c < m.n_cells(); ++c) {
    const Point<2> origin = node_of(m, c, 0);
    for (int b = 0; b < n_side; ++b)
      for (int a = 0; a < n_side; ++a) {
        const Point<2> p = node_of(m, c, local_index(n_side, a, b));
        EXPECT_TRUE(approx(p.x(), origin.x() + a * spacing, 0.0, coordinate_tol)) << c << ":" << a;
        EXPECT_TRUE(approx(p.y(), origin.y() + b * spacing, 0.0, coordinate_tol)) << c << ":" << b;
      }
  }
}

/// Does point p lie on the part of the boundary with this label (SPEC §4)?
bool lies_on(BoundaryLabel label, const Point<2>& p) {
  auto near = [](double a, double b) { return std::abs(a - b) <= coordinate_tol; };
  auto within = [](double v, double lo, double hi) {
    return v >= lo - coordinate_tol && v <= hi + coordinate_tol;
  };
  switch (label) {
  case BoundaryLabel::Rear: return near(p.x(), 0.0) && within(p.y(), 0.0, 10.0);
  case BoundaryLabel::Container: return near(p.y(), 10.0) && within(p.x(), 0.0, 10.0);
  case BoundaryLabel::Die: return near(p.x(), 10.0) && within(p.y(), 5.0, 10.0);
  case BoundaryLabel::FreeExit: return near(p.y(), 5.0) && within(p.x(), 10.0, 20.0);
  case BoundaryLabel::Front: return near(p.x(), 20.0) && within(p.y(), 0.0, 5.0);
  case BoundaryLabel::Symmetry: return near(p.y(), 0.0) && within(p.x(), 0.0, 20.0);
  case BoundaryLabel::FreeEntry: return false; // the benchmark channel has no Γ2
  }
  return false;
}

TEST_P(BenchmarkMesh, BoundaryLabelsHaveTheBenchmarkLengthsAndLieOnTheirLines) {
  const mesh::Mesh<2> m = make();
  std::map<BoundaryLabel, double> length;
  std::set<std::pair<Index, int>> seen;
  for (const mesh::BoundaryFacet& facet : m.facets) {
    EXPECT_TRUE(seen.insert({facet.cell, facet.local_face}).second) << "facet listed twice";
    const std::vector<int> local = mesh::face_local_nodes<2>(m.nodes_per_side(), facet.local_face);
    ASSERT_EQ(static_cast<int>(local.size()), m.nodes_per_side());
    for (int node : local)
      EXPECT_TRUE(lies_on(facet.label, node_of(m, facet.cell, node)))
          << mesh::label_name(facet.label) << " facet of cell " << facet.cell << " face "
          << facet.local_face;
    // Straight faces: the length is the distance between the end nodes.
    length[facet.label] +=
        (node_of(m, facet.cell, local.back()) - node_of(m, facet.cell, local.front())).norm();
  }
  // SPEC §4 geometry; the sums have ≤ 20 terms of round-off each.
  const std::map<BoundaryLabel, double> expected = {
      {BoundaryLabel::Rear, 10.0}, {BoundaryLabel::Container, 10.0},
      {BoundaryLabel::Die, 5.0},   {BoundaryLabel::FreeExit, 10.0},
      {BoundaryLabel::Front, 5.0}, {BoundaryLabel::Symmetry, 20.0},
  };
  for (const auto& [label, value] : expected)
    EXPECT_TRUE(approx(length[label], value, 1e-12)) << mesh::label_name(label);
  EXPECT_EQ(length.count(BoundaryLabel::FreeEntry), 0u);
  // Perimeter 60 made of faces of side `size`: every boundary face is listed.
  EXPECT_EQ(static_cast<double>(m.facets.size()), std::round(60.0 / GetParam().size));
}

INSTANTIATE_TEST_SUITE_P(ChannelMesh, BenchmarkMesh, ::testing::ValuesIn(benchmark_meshes),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ChannelMesh, UnequalGeometryPlacesTheDieAtTheContainerEnd) {
  // Container 3 long and 4 high, exit 2 long and 1 high: labels follow the geometry.
  const mesh::ChannelGeometry geometry{3.0, 4.0, 1.0, 2.0};
  const mesh::Mesh<2> m = mesh::make_channel_mesh(geometry, 0.5, 1);
  EXPECT_EQ(m.n_cells(), 6 * 8 + 4 * 2); // container 6×8, exit 4×2
  EXPECT_EQ(m.n_nodes(), 7 * 9 + 4 * 3); // container lattice 7×9, exit 4 columns of 3
  std::map<BoundaryLabel, double> length;
  for (const mesh::BoundaryFacet& facet : m.facets) {
    const auto local = mesh::face_local_nodes<2>(2, facet.local_face);
    const Point<2> p = node_of(m, facet.cell, local.front()),
                   q = node_of(m, facet.cell, local.back());
    length[facet.label] += (q - p).norm();
    if (facet.label == BoundaryLabel::Die) {
      EXPECT_TRUE(approx(p.x(), 3.0, 0.0, coordinate_tol));
      EXPECT_GE(std::min(p.y(), q.y()), 1.0 - coordinate_tol);
    }
  }
  // Round-off only.
  EXPECT_TRUE(approx(length[BoundaryLabel::Rear], 4.0, 1e-12));
  EXPECT_TRUE(approx(length[BoundaryLabel::Container], 3.0, 1e-12));
  EXPECT_TRUE(approx(length[BoundaryLabel::Die], 3.0, 1e-12));
  EXPECT_TRUE(approx(length[BoundaryLabel::FreeExit], 2.0, 1e-12));
  EXPECT_TRUE(approx(length[BoundaryLabel::Front], 1.0, 1e-12));
  EXPECT_TRUE(approx(length[BoundaryLabel::Symmetry], 5.0, 1e-12));
}

TEST(CellsAlong, AcceptsSizesThatFitAndRefusesOthers) {
  EXPECT_EQ(mesh::cells_along(10.0, 10.0 / 6.0), 6); // mesh I: 10/6 is inexact in binary
  EXPECT_EQ(mesh::cells_along(5.0, 10.0 / 6.0), 3);
  EXPECT_EQ(mesh::cells_along(10.0, 1.0), 10);
  EXPECT_EQ(mesh::cells_along(10.0, 10.0), 1);
  EXPECT_EQ(mesh::cells_along(10.0, 0.3), -1);  // 33.3… cells
  EXPECT_EQ(mesh::cells_along(10.0, 20.0), -1); // half a cell
  EXPECT_EQ(mesh::cells_along(10.0, 0.0), -1);
  EXPECT_EQ(mesh::cells_along(10.0, -1.0), -1);
  EXPECT_EQ(mesh::cells_along(0.0, 1.0), -1);
}

// Lexicographic numbering (x fastest) of a 3×3 cell:   6 7 8
//                                                      3 4 5
//                                                      0 1 2
// face 2·axis + side: 0 = left (ξ = −1), 1 = right, 2 = bottom (η = −1), 3 = top.
TEST(FaceLocalNodes, QuadraticQuadrilateralFacesByHand) {
  EXPECT_EQ(mesh::face_local_nodes<2>(3, 0), (std::vector<int>{0, 3, 6}));
  EXPECT_EQ(mesh::face_local_nodes<2>(3, 1), (std::vector<int>{2, 5, 8}));
  EXPECT_EQ(mesh::face_local_nodes<2>(3, 2), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(mesh::face_local_nodes<2>(3, 3), (std::vector<int>{6, 7, 8}));
}

TEST(FaceLocalNodes, LinearQuadrilateralAndHexahedronFacesByHand) {
  EXPECT_EQ(mesh::face_local_nodes<2>(2, 0), (std::vector<int>{0, 2}));
  EXPECT_EQ(mesh::face_local_nodes<2>(2, 1), (std::vector<int>{1, 3}));
  EXPECT_EQ(mesh::face_local_nodes<2>(2, 2), (std::vector<int>{0, 1}));
  EXPECT_EQ(mesh::face_local_nodes<2>(2, 3), (std::vector<int>{2, 3}));
  // Hexahedron: node = a + 2b + 4c.
  EXPECT_EQ(mesh::face_local_nodes<3>(2, 0), (std::vector<int>{0, 2, 4, 6}));
  EXPECT_EQ(mesh::face_local_nodes<3>(2, 1), (std::vector<int>{1, 3, 5, 7}));
  EXPECT_EQ(mesh::face_local_nodes<3>(2, 2), (std::vector<int>{0, 1, 4, 5}));
  EXPECT_EQ(mesh::face_local_nodes<3>(2, 3), (std::vector<int>{2, 3, 6, 7}));
  EXPECT_EQ(mesh::face_local_nodes<3>(2, 4), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(mesh::face_local_nodes<3>(2, 5), (std::vector<int>{4, 5, 6, 7}));
}

TEST(FaceLocalNodes, QuadraticHexahedronFacesHoldTheNineNodesOnTheirPlane) {
  for (int face = 0; face < 6; ++face) {
    const std::vector<int> nodes = mesh::face_local_nodes<3>(3, face);
    ASSERT_EQ(nodes.size(), 9u) << face;
    EXPECT_TRUE(std::is_sorted(nodes.begin(), nodes.end()));
    const int axis = face / 2, wanted = (face % 2 == 0) ? 0 : 2;
    for (int local : nodes) {
      const std::array<int, 3> index = {local % 3, (local / 3) % 3, local / 9};
      EXPECT_EQ(index[axis], wanted) << "face " << face << " node " << local;
    }
  }
}

TEST(BoundaryLabel, NamesAndContactParts) {
  EXPECT_EQ(mesh::label_name(BoundaryLabel::Rear), "rear");
  EXPECT_EQ(mesh::label_name(BoundaryLabel::FreeEntry), "free_entry");
  EXPECT_EQ(mesh::label_name(BoundaryLabel::Container), "container");
  EXPECT_EQ(mesh::label_name(BoundaryLabel::Die), "die");
  EXPECT_EQ(mesh::label_name(BoundaryLabel::FreeExit), "free_exit");
  EXPECT_EQ(mesh::label_name(BoundaryLabel::Front), "front");
  EXPECT_EQ(mesh::label_name(BoundaryLabel::Symmetry), "symmetry");
  EXPECT_TRUE(mesh::is_contact(BoundaryLabel::Container));
  EXPECT_TRUE(mesh::is_contact(BoundaryLabel::Die));
  EXPECT_FALSE(mesh::is_contact(BoundaryLabel::Rear));
  EXPECT_FALSE(mesh::is_contact(BoundaryLabel::FreeExit));
  EXPECT_FALSE(mesh::is_contact(BoundaryLabel::Symmetry));
}

} // namespace
} // namespace formflow::testing
