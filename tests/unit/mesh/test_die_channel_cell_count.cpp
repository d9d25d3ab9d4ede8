// SPDX-License-Identifier: MIT
// Counting the cells of a structured channel mesh without building it (the
// case validation's memory check relies on it).
#include "formflow/mesh/die_channel_mesh.hpp"

#include <gtest/gtest.h>

namespace formflow::mesh {
namespace {

ChannelGeometry small_channel(DieShape die) {
  ChannelGeometry geometry{2.0, 1.0, 0.75, 2.0};
  geometry.die = die;
  geometry.die_angle = 20.0;
  geometry.die_radius = 1.0;
  geometry.die_profile = {{0.0, 1.0}, {0.3, 0.9}, {1.0, 0.75}};
  return geometry;
}

TEST(DieChannelCellCount, EqualsTheCellsOfTheBuiltMesh) {
  for (DieShape die : {DieShape::Square, DieShape::Wedge, DieShape::Arc, DieShape::Polyline})
    for (Real land : {0.0, 0.5})
      for (Real size : {0.25, 0.125}) {
        ChannelGeometry geometry = small_channel(die);
        geometry.land_length = land;
        const Mesh<2> mesh = make_die_channel_mesh(geometry, size, 1);
        EXPECT_EQ(die_channel_cell_count(geometry, size), static_cast<Real>(mesh.n_cells()))
            << "die " << static_cast<int>(die) << ", land " << land << ", size " << size;
      }
}

TEST(DieChannelCellCount, GrowsAsOneOverSizeSquaredWithoutOverflow) {
  // The benchmark channel at h = 1e-5 has 1.5e12 cells: more than any int.
  const ChannelGeometry benchmark;
  EXPECT_EQ(die_channel_cell_count(benchmark, 1.0), 150.0);
  EXPECT_NEAR(die_channel_cell_count(benchmark, 1e-5), 1.5e12, 1e-3 * 1.5e12);
}

} // namespace
} // namespace formflow::mesh
