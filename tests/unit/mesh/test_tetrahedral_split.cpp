// SPDX-License-Identifier: MIT
// Hexahedra cut into tetrahedra (mesh/tetrahedral_split.hpp): positive volumes summing to
// the hexahedra's, every triangle shared by at most two tetrahedra, the faces used once
// exactly the labelled facets (each part's area kept), also when the node numbering is
// scrambled so that cells need the centre node; P2 nodes halfway along straight edges.
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"
#include "formflow/mesh/tetrahedral_split.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <vector>

namespace formflow::testing {
namespace {

/// Σ JxW over the cells at their full rule; `valid` false where a Jacobian is not positive.
Real split_test_volume(const mesh::Mesh<3>& mesh, bool& valid) {
  const mesh::CellType type = mesh.cell_type();
  fem::CellValues<3> values(type, fem::full_rule<3>(type));
  fem::CellValues<3>::Gradients coordinates(3, mesh.nodes_per_cell());
  Real total = 0;
  valid = true;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    valid = valid && values.reinit(coordinates);
    for (int q = 0; q < values.n_points(); ++q) total += values.JxW(q);
  }
  return total;
}

/// Area of the facets of each label.
std::map<mesh::BoundaryLabel, Real> split_test_areas(const mesh::Mesh<3>& mesh) {
  const mesh::CellType type = mesh.cell_type();
  fem::FacetValues<3> face(type, fem::face_rule<3>(type));
  fem::FacetValues<3>::Gradients coordinates(3, mesh.nodes_per_cell());
  std::map<mesh::BoundaryLabel, Real> areas;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, facet.cell));
    face.reinit(coordinates, facet.local_face);
    for (int q = 0; q < face.n_points(); ++q) areas[facet.label] += face.JxW(q);
  }
  return areas;
}

using FaceKey = std::array<Index, 3>;

FaceKey split_test_face(const mesh::Mesh<3>& mesh, Index cell, int face) {
  const std::vector<int> vertices = mesh::simplex_face_vertices<3>(face);
  FaceKey key{mesh.cells(vertices[0], cell), mesh.cells(vertices[1], cell),
              mesh.cells(vertices[2], cell)};
  std::sort(key.begin(), key.end());
  return key;
}

/// Conformity: a triangle is a face of one or two tetrahedra, and those of one are the
/// facets, each listed once.
void expect_conforming(const mesh::Mesh<3>& mesh) {
  std::map<FaceKey, int> uses;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int face = 0; face < 4; ++face) ++uses[split_test_face(mesh, cell, face)];
  std::map<FaceKey, int> boundary;
  for (const auto& [key, count] : uses) {
    ASSERT_LE(count, 2) << "a triangle of more than two tetrahedra";
    if (count == 1) boundary[key] = 0;
  }
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    const auto found = boundary.find(split_test_face(mesh, facet.cell, facet.local_face));
    ASSERT_NE(found, boundary.end()) << "a facet that two tetrahedra share";
    ++found->second;
  }
  for (const auto& [key, count] : boundary) EXPECT_EQ(count, 1) << "a boundary face unlabelled";
}

/// The rectangle quarter model of tests/unit/mesh/test_solid_channel_mesh.cpp's size.
mesh::Mesh<3> split_test_bar(int order) {
  mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0};
  mesh::SolidChannel channel;
  channel.section = mesh::ChannelSection::Rectangle;
  channel.entry_half_width = 1.5;
  channel.exit_half_width = 0.5;
  return mesh::make_solid_channel_mesh(geometry, channel, 0.5, order, false);
}

/// `mesh` with its node numbers permuted at random (the same mesh, other global numbers).
mesh::Mesh<3> renumbered(mesh::Mesh<3> mesh, unsigned seed) {
  std::vector<Index> number(static_cast<std::size_t>(mesh.n_nodes()));
  std::iota(number.begin(), number.end(), Index(0));
  std::shuffle(number.begin(), number.end(), std::mt19937(seed));
  Eigen::Matrix<Real, 3, Eigen::Dynamic> nodes(3, mesh.n_nodes());
  for (Index n = 0; n < mesh.n_nodes(); ++n) nodes.col(number[n]) = mesh.nodes.col(n);
  mesh.nodes = nodes;
  for (Index& node : mesh.cells.reshaped()) node = number[node];
  return mesh;
}

// Volumes and areas are sums of positive terms of the same magnitude: each sum's round-off
// is below its term count times ε relative to the sum.
Real sum_tolerance(Index terms, Real sum) {
  return 4.0 * static_cast<Real>(terms) * std::numeric_limits<Real>::epsilon() * sum;
}

class TetrahedralSplit : public ::testing::TestWithParam<int> {};

TEST_P(TetrahedralSplit, KeepsVolumeAreasAndConformity) {
  const int order = GetParam();
  for (const unsigned seed : {0u, 1u, 2u}) {
    SCOPED_TRACE(seed == 0 ? "structured numbering" : "scrambled numbering");
    const mesh::Mesh<3> hexahedra =
        seed == 0 ? split_test_bar(order) : renumbered(split_test_bar(order), seed);
    const mesh::Mesh<3> tetrahedra = mesh::split_into_tetrahedra(hexahedra, false);
    EXPECT_TRUE(tetrahedra.is_simplex());
    EXPECT_EQ(tetrahedra.facets.size(), 2 * hexahedra.facets.size());
    if (seed == 0) { // the lattice's own numbering: every cell a Kuhn cell, no node added
      EXPECT_EQ(tetrahedra.n_cells(), 6 * hexahedra.n_cells());
      EXPECT_EQ(tetrahedra.n_nodes(), hexahedra.n_nodes());
    } else { // some cells need a centre: twelve tetrahedra and (Q1) a node each
      EXPECT_GT(tetrahedra.n_cells(), 6 * hexahedra.n_cells());
    }
    bool hex_valid = false, tet_valid = false;
    const Real hex_volume = split_test_volume(hexahedra, hex_valid);
    const Real tet_volume = split_test_volume(tetrahedra, tet_valid);
    EXPECT_TRUE(hex_valid);
    EXPECT_TRUE(tet_valid); // every tetrahedron positively oriented
    EXPECT_NEAR(tet_volume, hex_volume, sum_tolerance(tetrahedra.n_cells() * 64, hex_volume));
    const auto hex_areas = split_test_areas(hexahedra);
    const auto tet_areas = split_test_areas(tetrahedra);
    ASSERT_EQ(tet_areas.size(), hex_areas.size());
    for (const auto& [label, area] : hex_areas)
      EXPECT_NEAR(tet_areas.at(label), area,
                  sum_tolerance(Index(tetrahedra.facets.size()) * 16, area))
          << mesh::label_name(label);
    expect_conforming(tetrahedra);
  }
}

TEST_P(TetrahedralSplit, MidpointsLieHalfwayAlongTheStraightEdges) {
  if (GetParam() != 2) GTEST_SKIP() << "P1 has no edge nodes";
  // The bar's cells are boxes: every edge straight, so each P2 node is its edge's midpoint.
  const mesh::Mesh<3> tetrahedra =
      mesh::split_into_tetrahedra(renumbered(split_test_bar(2), 3), false);
  const Real scale = tetrahedra.nodes.cwiseAbs().maxCoeff();
  for (Index cell = 0; cell < tetrahedra.n_cells(); ++cell)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const Point<3> mid = 0.5 * (tetrahedra.nodes.col(tetrahedra.cells(a, cell)) +
                                    tetrahedra.nodes.col(tetrahedra.cells(b, cell)));
        const Point<3> node =
            tetrahedra.nodes.col(tetrahedra.cells(mesh::simplex_edge_midpoint<3>(a, b), cell));
        EXPECT_LE((node - mid).norm(), 4 * std::numeric_limits<Real>::epsilon() * scale);
      }
}

TEST(TetrahedralSplit, BubblesFollowTheSplit) {
  const mesh::Mesh<3> plain = mesh::split_into_tetrahedra(split_test_bar(2), false);
  const mesh::Mesh<3> enriched = mesh::split_into_tetrahedra(split_test_bar(2), true);
  EXPECT_TRUE(enriched.bubbles);
  EXPECT_EQ(enriched.nodes_per_cell(), 15); // P2+: 10, four face centroids and one cell's
  EXPECT_EQ(enriched.cells.topRows(10), plain.cells);
}

INSTANTIATE_TEST_SUITE_P(Orders, TetrahedralSplit, ::testing::Values(1, 2),
                         [](const auto& info) { return "Order" + std::to_string(info.param); });

} // namespace
} // namespace formflow::testing
