// SPDX-License-Identifier: MIT
// The symmetry planes of the solid channels as plane meshes (io/plot/solid_section.hpp):
// the z = 0 plane of a rectangle or round quarter model is the plane channel of the
// same (x, y) geometry, cell for cell and label for label; the rectangle's y = 0 plane
// is the channel of its half widths.
#include "formflow/io/plot/solid_section.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"

#include <gtest/gtest.h>

#include <map>
#include <tuple>

namespace formflow::testing {
namespace {

using mesh::BoundaryLabel;
using mesh::ChannelSection;
using mesh::DieShape;

std::map<BoundaryLabel, int> label_counts(const mesh::Mesh<2>& mesh) {
  std::map<BoundaryLabel, int> counts;
  for (const mesh::BoundaryFacet& facet : mesh.facets) ++counts[facet.label];
  return counts;
}

/// Positive corner area of every cell: the section is drawn as the plane pictures expect.
bool positively_oriented(const mesh::Mesh<2>& mesh) {
  const int n = mesh.nodes_per_side();
  for (Index c = 0; c < mesh.n_cells(); ++c) {
    const auto p = [&](int a, int b) { return Point<2>(mesh.nodes.col(mesh.cells(b * n + a, c))); };
    const Point<2> d1 = p(n - 1, n - 1) - p(0, 0), d2 = p(0, n - 1) - p(n - 1, 0);
    if (d1.x() * d2.y() - d1.y() * d2.x() <= 0) return false;
  }
  return true;
}

class SolidSection : public ::testing::TestWithParam<std::tuple<int, ChannelSection, DieShape>> {};

TEST_P(SolidSection, TheZPlaneIsThePlaneChannelAndTheYPlaneTheChannelOfTheWidths) {
  const auto [order, section, die] = GetParam();
  mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0};
  geometry.die = die;
  geometry.die_angle = 45.0;
  mesh::SolidChannel solid;
  solid.section = section;
  solid.entry_half_width = 1.5;
  solid.exit_half_width = 0.5;
  const mesh::Mesh<3> model = mesh::make_solid_channel_mesh(geometry, solid, 0.5, order, false);

  const io::plot::PlaneSection z0 = io::plot::symmetry_section(model, 2);
  const mesh::Mesh<2> plane = mesh::make_die_channel_mesh(geometry, 0.5, order);
  EXPECT_EQ(z0.mesh.n_cells(), plane.n_cells());
  EXPECT_EQ(z0.mesh.n_nodes(), plane.n_nodes());
  EXPECT_EQ(label_counts(z0.mesh), label_counts(plane));
  EXPECT_TRUE(positively_oriented(z0.mesh));
  for (std::size_t k = 0; k < z0.solid_node.size(); ++k) {
    EXPECT_EQ(model.nodes(2, z0.solid_node[k]), 0.0);
    EXPECT_EQ(z0.mesh.nodes(1, static_cast<Index>(k)), model.nodes(1, z0.solid_node[k]));
  }

  const io::plot::PlaneSection y0 = io::plot::symmetry_section(model, 1);
  EXPECT_TRUE(positively_oriented(y0.mesh));
  mesh::ChannelGeometry widths = geometry; // the rectangle's (x, z) channel
  if (section == ChannelSection::Rectangle) {
    widths.entry_half_height = solid.entry_half_width;
    widths.exit_half_height = solid.exit_half_width;
  }
  if (section == ChannelSection::Rectangle && die != DieShape::Square) {
    // The swept rectangle keeps the plane channel's columns: only the label counts
    // of the square die's lattice would differ.
    EXPECT_EQ(y0.mesh.n_cells(), plane.n_cells() / 4 * 3); // 3 of the 4 rows' widths
  } else {
    const mesh::Mesh<2> side = mesh::make_die_channel_mesh(widths, 0.5, order);
    EXPECT_EQ(y0.mesh.n_cells(), side.n_cells());
    EXPECT_EQ(label_counts(y0.mesh), label_counts(side));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Sections, SolidSection,
    ::testing::Values(std::make_tuple(1, ChannelSection::Rectangle, DieShape::Square),
                      std::make_tuple(2, ChannelSection::Rectangle, DieShape::Square),
                      std::make_tuple(2, ChannelSection::Rectangle, DieShape::Wedge),
                      std::make_tuple(1, ChannelSection::Round, DieShape::Wedge),
                      std::make_tuple(2, ChannelSection::Round, DieShape::Wedge)));

} // namespace
} // namespace formflow::testing
