// SPDX-License-Identifier: MIT
// The plane channel extruded into hexahedra (the 3D slab): counts, positive Jacobians,
// the volume, and every boundary face labelled once with the plane label or `symmetry`.
#include "formflow/fem/cell_values.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/extruded_mesh.hpp"
#include "formflow/mesh/facet_axis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

namespace formflow::testing {
namespace {

using mesh::BoundaryLabel;

/// A small channel {L_c = 2, H_in = 2, H_out = 1, L_e = 2} at h = 0.5.
mesh::ChannelGeometry small_channel(mesh::DieShape die) {
  mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0};
  geometry.die = die;
  geometry.die_angle = 45.0;
  return geometry;
}

/// Sum of JxW over a mesh's cells at the full Gauss rule; false in `valid` if any
/// cell has a non-positive Jacobian at a Gauss point or a node.
template <int dim> Real measure(const mesh::Mesh<dim>& mesh, bool& valid) {
  fem::CellValues<dim> at_gauss(mesh.order, fem::gauss_rule<dim>(mesh.order + 1));
  fem::CellValues<dim> at_nodes(mesh.order, fem::nodal_rule<dim>(mesh.order + 1));
  typename fem::CellValues<dim>::Gradients coordinates(dim, mesh.nodes_per_cell());
  Real total = 0.0;
  valid = true;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    valid = valid && at_gauss.reinit(coordinates) && at_nodes.reinit(coordinates);
    for (int q = 0; q < at_gauss.n_points(); ++q) total += at_gauss.JxW(q);
  }
  return total;
}

/// The faces of a hexahedral mesh that belong to one cell only, as sorted node sets
/// → (cell, local face): the boundary, found from the connectivity alone.
std::map<std::vector<Index>, std::pair<Index, int>> boundary_faces(const mesh::Mesh<3>& mesh) {
  std::map<std::vector<Index>, std::vector<std::pair<Index, int>>> seen;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (int face = 0; face < 6; ++face) {
      std::vector<Index> nodes;
      for (int local : mesh::face_local_nodes<3>(mesh.nodes_per_side(), face))
        nodes.push_back(mesh.cells(local, cell));
      std::sort(nodes.begin(), nodes.end());
      seen[nodes].push_back({cell, face});
    }
  std::map<std::vector<Index>, std::pair<Index, int>> boundary;
  for (const auto& [nodes, owners] : seen) {
    EXPECT_LE(owners.size(), 2u) << "a face shared by more than two cells";
    if (owners.size() == 1) boundary[nodes] = owners.front();
  }
  return boundary;
}

class ExtrudedChannel : public ::testing::TestWithParam<std::tuple<int, mesh::DieShape>> {};

TEST_P(ExtrudedChannel, HexahedraOfTheChannelInLayersWithEveryBoundaryFaceLabelledOnce) {
  const auto [order, die] = GetParam();
  const mesh::ChannelGeometry geometry = small_channel(die);
  const mesh::Mesh<2> plane = mesh::make_die_channel_mesh(geometry, 0.5, order);
  const Real thickness = 0.75;
  const int layers = 3;
  const mesh::Mesh<3> slab = mesh::extrude_mesh(plane, thickness, layers, BoundaryLabel::Symmetry);

  EXPECT_EQ(slab.order, order);
  EXPECT_EQ(slab.n_cells(), layers * plane.n_cells());
  EXPECT_EQ(slab.nodes_per_cell(), (order + 1) * (order + 1) * (order + 1));
  EXPECT_EQ(slab.n_nodes(), (order * layers + 1) * plane.n_nodes());

  // Volume = area × thickness: the Gauss rules are exact for these maps (affine in z),
  // so only rounding separates the two (1e-12 relative: a few hundred cells' sums).
  bool plane_valid = false, slab_valid = false;
  const Real area = measure(plane, plane_valid);
  const Real volume = measure(slab, slab_valid);
  EXPECT_TRUE(plane_valid);
  EXPECT_TRUE(slab_valid) << "a hexahedron with a non-positive Jacobian";
  EXPECT_NEAR(volume, area * thickness, 1e-12 * volume);

  // Every face on one cell only is a labelled facet, and every facet is such a face.
  const auto boundary = boundary_faces(slab);
  EXPECT_EQ(boundary.size(), slab.facets.size());
  std::map<BoundaryLabel, int> per_label, plane_per_label;
  for (const mesh::BoundaryFacet& facet : plane.facets) ++plane_per_label[facet.label];
  for (const mesh::BoundaryFacet& facet : slab.facets) {
    std::vector<Index> nodes;
    for (int local : mesh::face_local_nodes<3>(slab.nodes_per_side(), facet.local_face))
      nodes.push_back(slab.cells(local, facet.cell));
    std::sort(nodes.begin(), nodes.end());
    const auto found = boundary.find(nodes);
    ASSERT_NE(found, boundary.end()) << "facet of cell " << facet.cell << " is interior";
    EXPECT_EQ(found->second, std::make_pair(facet.cell, facet.local_face));
    ++per_label[facet.label];
    // The z faces lie on z = 0 and z = thickness; the others are the plane facets'.
    if (facet.local_face >= 4) {
      EXPECT_EQ(facet.label, BoundaryLabel::Symmetry);
      const Real z = facet.local_face == 4 ? 0.0 : thickness;
      for (Index node : nodes) EXPECT_EQ(slab.nodes(2, node), z);
    }
  }
  // Each plane facet once per layer; the two z faces of every plane cell are symmetry.
  for (auto [label, count] : plane_per_label)
    EXPECT_EQ(per_label[label],
              layers * count + (label == BoundaryLabel::Symmetry ? 2 * plane.n_cells() : 0))
        << mesh::label_name(label);
  EXPECT_EQ(per_label.size(), plane_per_label.size());
}

INSTANTIATE_TEST_SUITE_P(OrdersAndDies, ExtrudedChannel,
                         ::testing::Combine(::testing::Values(1, 2),
                                            ::testing::Values(mesh::DieShape::Square,
                                                              mesh::DieShape::Wedge)));

TEST(ExtrusionLayers, AboutTheCellSideAndAtLeastOne) {
  EXPECT_EQ(mesh::extrusion_layers(1.0, 0.5), 2);
  EXPECT_EQ(mesh::extrusion_layers(1.0, 0.3), 3);  // 3.33
  EXPECT_EQ(mesh::extrusion_layers(1.0, 0.28), 4); // 3.57
  EXPECT_EQ(mesh::extrusion_layers(0.1, 1.0), 1);  // thinner than one cell: one layer
}

TEST(FacetNormalAxis, CoordinatePlanesOfTheSlabAndNoneOnTheWedgeFace) {
  const mesh::Mesh<2> plane =
      mesh::make_die_channel_mesh(small_channel(mesh::DieShape::Wedge), 0.5, 2);
  const mesh::Mesh<3> slab = mesh::extrude_mesh(plane, 1.0, 2, BoundaryLabel::Symmetry);
  int tilted = 0;
  for (const mesh::BoundaryFacet& facet : slab.facets) {
    const std::optional<int> axis = mesh::facet_normal_axis(slab, facet);
    if (facet.label == BoundaryLabel::Die) {
      // The 45° wedge face is tilted: no coordinate plane.
      EXPECT_FALSE(axis.has_value());
      tilted += !axis.has_value();
      continue;
    }
    ASSERT_TRUE(axis.has_value()) << mesh::label_name(facet.label);
    // Faces 2·axis and 2·axis + 1 are normal to that axis in a lexicographic cell.
    EXPECT_EQ(*axis, facet.local_face / 2) << mesh::label_name(facet.label);
  }
  EXPECT_GT(tilted, 0);
  for (const mesh::BoundaryFacet& facet : plane.facets) {
    if (facet.label == BoundaryLabel::Symmetry) {
      EXPECT_EQ(mesh::facet_normal_axis(plane, facet).value_or(-1), 1);
    }
  }
}

} // namespace
} // namespace formflow::testing
