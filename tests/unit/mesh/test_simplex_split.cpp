// SPDX-License-Identifier: MIT
// Triangles cut from the die-channel mesh: the same domain, boundary and labels, valid
// cells, the bubble nodes where the P1b / P2+ layouts put them.
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/simplex_split.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <set>

namespace formflow::testing {
namespace {

// Areas and lengths are sums of O(100) positive terms of O(1) on a domain of O(100):
// their round-off is a few hundred ulps of the total, far below 1e-12 relative.
constexpr double split_sum_roundoff = 1e-12;

struct Measures {
  Real area = 0.0;
  std::array<Real, mesh::n_boundary_labels> length{};
  bool all_positive = true;
};

Measures measures_of(const mesh::Mesh<2>& mesh) {
  Measures result;
  fem::CellValues<2> cells(mesh.cell_type(), fem::full_rule<2>(mesh.cell_type()));
  fem::FacetValues<2> faces(mesh.cell_type(), fem::face_rule<2>(mesh.cell_type()));
  typename fem::CellValues<2>::Gradients nodes(2, mesh.nodes_per_cell());
  const auto gather = [&](Index cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      nodes.col(a) = mesh.nodes.col(mesh.cells(a, cell));
  };
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    gather(cell);
    result.all_positive = cells.reinit(nodes) && result.all_positive;
    for (int q = 0; q < cells.n_points(); ++q) result.area += cells.JxW(q);
  }
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    gather(facet.cell);
    faces.reinit(nodes, facet.local_face);
    for (int q = 0; q < faces.n_points(); ++q)
      result.length[static_cast<int>(facet.label)] += faces.JxW(q);
  }
  return result;
}

class SimplexSplit : public ::testing::TestWithParam<std::pair<int, bool>> {};

TEST_P(SimplexSplit, KeepsTheDomainTheBoundaryAndItsLabels) {
  const auto [order, bubbles] = GetParam();
  const mesh::Mesh<2> quadrilaterals = mesh::make_die_channel_mesh({}, 1.0, order);
  const mesh::Mesh<2> triangles = mesh::split_into_triangles(quadrilaterals, bubbles);
  ASSERT_TRUE(triangles.is_simplex());
  EXPECT_EQ(triangles.n_cells(), 2 * quadrilaterals.n_cells());
  EXPECT_EQ(triangles.nodes_per_cell(), mesh::nodes_per_cell<2>(triangles.cell_type()));
  EXPECT_EQ(triangles.facets.size(), quadrilaterals.facets.size());
  const Measures before = measures_of(quadrilaterals), after = measures_of(triangles);
  EXPECT_TRUE(after.all_positive);
  EXPECT_TRUE(approx(after.area, before.area, split_sum_roundoff, 0.0));
  for (int label = 0; label < mesh::n_boundary_labels; ++label)
    EXPECT_TRUE(approx(after.length[label], before.length[label], split_sum_roundoff, 1e-14))
        << mesh::label_name(static_cast<mesh::BoundaryLabel>(label));
  // Each facet keeps its nodes: the triangle's side is the quadrilateral's.
  for (std::size_t f = 0; f < triangles.facets.size(); ++f) {
    std::set<Index> old_nodes, new_nodes;
    const mesh::BoundaryFacet &was = quadrilaterals.facets[f], &is = triangles.facets[f];
    for (int local : quadrilaterals.face_nodes(was.local_face))
      old_nodes.insert(quadrilaterals.cells(local, was.cell));
    for (int local : triangles.face_nodes(is.local_face))
      new_nodes.insert(triangles.cells(local, is.cell));
    EXPECT_EQ(old_nodes, new_nodes) << "facet " << f;
    EXPECT_EQ(was.label, is.label);
  }
}

TEST(SimplexSplitBubbles, PutsEachBubbleNodeAtItsTrianglesCentroid) {
  for (const int order : {1, 2}) {
    const mesh::Mesh<2> triangles =
        mesh::split_into_triangles(mesh::make_die_channel_mesh({}, 1.0, order), true);
    ASSERT_TRUE(triangles.bubbles);
    const int centroid_node = triangles.nodes_per_cell() - 1;
    for (Index cell = 0; cell < triangles.n_cells(); ++cell) {
      Point<2> centroid = Point<2>::Zero();
      for (int v = 0; v < 3; ++v) centroid += triangles.nodes.col(triangles.cells(v, cell)) / 3.0;
      // Straight-sided cells: the P2 map of the reference centroid is the vertices' mean
      // (a sum of six O(10) terms: 1e-13 relative is round-off).
      EXPECT_LE((triangles.nodes.col(triangles.cells(centroid_node, cell)) - centroid).norm(),
                1e-13 * (1.0 + centroid.norm()))
          << "order " << order << ", cell " << cell;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(OrdersAndBubbles, SimplexSplit,
                         ::testing::Values(std::pair{1, false}, std::pair{1, true},
                                           std::pair{2, false}, std::pair{2, true}));

} // namespace
} // namespace formflow::testing
