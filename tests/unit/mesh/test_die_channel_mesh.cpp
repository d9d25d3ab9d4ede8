// SPDX-License-Identifier: MIT
// Mapped meshes of wedge, arc and polyline dies: the die face is followed exactly,
// areas, labels, the land, the drawing relabel and the face normals on the sloped die.
#include "formflow/mesh/die_channel_mesh.hpp"

#include "formflow/fem/cell_values.hpp"
#include "formflow/mesh/die_profile.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

namespace formflow::testing {
namespace {

using mesh::BoundaryLabel;
using mesh::DieShape;

mesh::ChannelGeometry wedge(Real degrees) {
  mesh::ChannelGeometry geometry{2.0, 1.0, 0.75, 2.0};
  geometry.die = DieShape::Wedge;
  geometry.die_angle = degrees;
  return geometry;
}

typename fem::CellValues<2>::Gradients cell_nodes(const mesh::Mesh<2>& m, Index cell) {
  typename fem::CellValues<2>::Gradients nodes(2, m.nodes_per_cell());
  for (int a = 0; a < m.nodes_per_cell(); ++a) nodes.col(a) = m.nodes.col(m.cells(a, cell));
  return nodes;
}

Real mesh_area(const mesh::Mesh<2>& m) {
  fem::CellValues<2> values(m.order, fem::gauss_rule<2>(m.order + 1));
  Real area = 0.0;
  for (Index cell = 0; cell < m.n_cells(); ++cell) {
    EXPECT_TRUE(values.reinit(cell_nodes(m, cell))) << "inverted cell " << cell;
    for (int q = 0; q < values.n_points(); ++q) area += values.JxW(q);
  }
  return area;
}

/// Every node of a Die facet lies on the die face y = h(x) (or the land y = H_out).
void expect_die_nodes_on_face(const mesh::Mesh<2>& m, const mesh::ChannelGeometry& geometry) {
  const mesh::DieProfile profile(geometry);
  int checked = 0;
  for (const mesh::BoundaryFacet& facet : m.facets) {
    if (facet.label != BoundaryLabel::Die) continue;
    for (int local : mesh::face_local_nodes<2>(m.nodes_per_side(), facet.local_face)) {
      const Point<2> node = m.nodes.col(m.cells(local, facet.cell));
      // Coordinates are products of O(1) values: 1e-12 is round-off.
      EXPECT_TRUE(approx(node.y(), profile.height(node.x() - geometry.container_length), 0, 1e-12))
          << node.transpose();
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(DieChannelMesh, WedgeFollowsTheFaceAndHasTheChannelArea) {
  for (int order : {1, 2}) {
    const mesh::ChannelGeometry geometry = wedge(10.0);
    const mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.125, order);
    expect_die_nodes_on_face(m, geometry);
    const Real die_length = 0.25 / std::tan(10.0 * std::numbers::pi / 180.0);
    const Real exact = 2.0 * 1.0 + die_length * (1.0 + 0.75) / 2 + 2.0 * 0.75;
    // Straight-sided cells represent the channel exactly: round-off only.
    EXPECT_TRUE(approx(mesh_area(m), exact, 1e-12));
    EXPECT_TRUE(approx(m.nodes.row(0).maxCoeff(), 4.0 + die_length, 1e-14));
  }
}

TEST(DieChannelMesh, LabelsCoverTheBoundaryOnce) {
  const mesh::ChannelGeometry geometry = wedge(15.0);
  const mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.25, 2);
  std::map<BoundaryLabel, int> count;
  for (const auto& facet : m.facets) ++count[facet.label];
  const int rows = 4, container = 8, exit = 8;
  const int die =
      static_cast<int>(std::ceil(0.25 / std::tan(15.0 * std::numbers::pi / 180.0) / 0.25));
  EXPECT_EQ(count[BoundaryLabel::Rear], rows);
  EXPECT_EQ(count[BoundaryLabel::Front], rows);
  EXPECT_EQ(count[BoundaryLabel::Symmetry], container + die + exit);
  EXPECT_EQ(count[BoundaryLabel::Container], container);
  EXPECT_EQ(count[BoundaryLabel::Die], die);
  EXPECT_EQ(count[BoundaryLabel::FreeExit], exit);
}

TEST(DieChannelMesh, LandIsDieContactAndDrawingFreesTheContainer) {
  mesh::ChannelGeometry geometry = wedge(15.0);
  geometry.land_length = 0.5;
  mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.25, 1);
  const Real land_start = mesh::die_exit_position(geometry);
  int land = 0;
  for (const auto& facet : m.facets) {
    if (facet.label != BoundaryLabel::Die) continue;
    const auto face = mesh::face_local_nodes<2>(2, facet.local_face);
    const Point<2> a = m.nodes.col(m.cells(face.front(), facet.cell));
    if (a.x() >= land_start - 1e-12) {
      ++land;
      EXPECT_TRUE(approx(a.y(), 0.75, 0, 1e-14));
    }
  }
  EXPECT_EQ(land, 2);
  mesh::free_container_wall(m);
  for (const auto& facet : m.facets) EXPECT_NE(facet.label, BoundaryLabel::Container);

  mesh::ChannelGeometry square; // the benchmark with a land of 2
  square.land_length = 2.0;
  const mesh::Mesh<2> benchmark = mesh::make_die_channel_mesh(square, 1.0, 2);
  int square_land = 0;
  for (const auto& facet : benchmark.facets)
    if (facet.label == BoundaryLabel::Die && facet.local_face == 3) ++square_land;
  EXPECT_EQ(square_land, 2);
}

TEST(DieChannelMesh, ArcQ2MidNodesLieOnTheCircle) {
  mesh::ChannelGeometry geometry = wedge(0.0);
  geometry.die = DieShape::Arc;
  geometry.die_radius = 1.0;
  const mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.0625, 2);
  expect_die_nodes_on_face(m, geometry);
  const Real length = mesh::DieProfile(geometry).length();
  const Point<2> centre(2.0 + length, 0.75 + 1.0);
  for (const auto& facet : m.facets) {
    if (facet.label != BoundaryLabel::Die) continue;
    for (int local : mesh::face_local_nodes<2>(3, facet.local_face)) {
      EXPECT_TRUE(approx((m.nodes.col(m.cells(local, facet.cell)) - centre).norm(), 1.0, 0, 1e-12));
    }
  }
  // Area: ∫ h dx = L (H_out + R) − ∫₀^L √(R² − s²) ds under the arc. Q2 cells
  // follow the circle to O(h³) in position, so the area agrees to ~1e-8 here.
  const Real integral = 0.5 * (length * std::sqrt(1 - length * length) + std::asin(length));
  const Real exact = 2.0 + length * (0.75 + 1.0) - integral + 2.0 * 0.75;
  EXPECT_TRUE(approx(mesh_area(m), exact, 1e-8));
}

TEST(DieChannelMesh, PolylineKinksAreMeshNodes) {
  mesh::ChannelGeometry geometry = wedge(0.0);
  geometry.die = DieShape::Polyline;
  geometry.die_profile = {{0.0, 1.0}, {0.3, 0.9}, {1.0, 0.75}};
  const mesh::Mesh<2> m = mesh::make_die_channel_mesh(geometry, 0.125, 1);
  expect_die_nodes_on_face(m, geometry);
  bool kink = false;
  for (Index n = 0; n < m.n_nodes(); ++n)
    kink = kink || (std::abs(m.nodes(0, n) - 2.3) < 1e-12 && std::abs(m.nodes(1, n) - 0.9) < 1e-12);
  EXPECT_TRUE(kink);
  const Real exact = 2.0 + 0.3 * 0.95 + 0.7 * 0.825 + 2.0 * 0.75;
  EXPECT_TRUE(approx(mesh_area(m), exact, 1e-12));
}

TEST(DieChannelMesh, FaceNormalsOnTheSlopedDieAreTheConeNormal) {
  for (int order : {1, 2}) {
    const Real degrees = 20.0, alpha = degrees * std::numbers::pi / 180.0;
    const mesh::Mesh<2> m = mesh::make_die_channel_mesh(wedge(degrees), 0.125, order);
    fem::FacetValues<2> values(order, fem::gauss_rule<1>(order + 1));
    int checked = 0;
    for (const auto& facet : m.facets) {
      if (facet.label != BoundaryLabel::Die) continue;
      values.reinit(cell_nodes(m, facet.cell), facet.local_face);
      for (int q = 0; q < values.n_points(); ++q) {
        // Outward from the metal into the die: up and forward, (sin α, cos α).
        EXPECT_TRUE(approx(values.normal(q).x(), std::sin(alpha), 0, 1e-12));
        EXPECT_TRUE(approx(values.normal(q).y(), std::cos(alpha), 0, 1e-12));
        ++checked;
      }
    }
    EXPECT_GT(checked, 0);
  }
}

} // namespace
} // namespace formflow::testing
