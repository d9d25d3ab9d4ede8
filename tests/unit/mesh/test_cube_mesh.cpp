// SPDX-License-Identifier: MIT
// The unit cube of the 3D manufactured solutions: distorted but valid hexahedra that
// tile the cube exactly, every boundary face labelled on its face of the cube.
#include "formflow/fem/cell_values.hpp"
#include "formflow/mesh/cube_mesh.hpp"
#include "formflow/mesh/facet_axis.hpp"

#include <gtest/gtest.h>

#include <tuple>

namespace formflow::testing {
namespace {

class CubeMesh : public ::testing::TestWithParam<std::tuple<int, mesh::Distortion>> {};

TEST_P(CubeMesh, ValidCellsTileTheCubeAndTheFacesAreLabelled) {
  const auto [order, distortion] = GetParam();
  const int n = 4;
  const mesh::BoxDistortion how{distortion, distortion == mesh::Distortion::Random ? 0.2 : 0.1, 1};
  const mesh::Mesh<3> cube = mesh::make_unit_cube_mesh(n, order, how);
  EXPECT_EQ(cube.n_cells(), n * n * n);
  EXPECT_EQ(cube.n_nodes(), (n * order + 1) * (n * order + 1) * (n * order + 1));
  fem::CellValues<3> at_gauss(order, fem::gauss_rule<3>(order + 1));
  fem::CellValues<3> at_nodes(order, fem::nodal_rule<3>(order + 1));
  fem::CellValues<3>::Gradients coordinates(3, cube.nodes_per_cell());
  Real volume = 0.0;
  bool distorted = false;
  for (Index cell = 0; cell < cube.n_cells(); ++cell) {
    for (int a = 0; a < cube.nodes_per_cell(); ++a)
      coordinates.col(a) = cube.nodes.col(cube.cells(a, cell));
    ASSERT_TRUE(at_gauss.reinit(coordinates) && at_nodes.reinit(coordinates)) << cell;
    Real cell_volume = 0.0;
    for (int q = 0; q < at_gauss.n_points(); ++q) cell_volume += at_gauss.JxW(q);
    distorted = distorted || std::abs(cell_volume * n * n * n - 1) > 1e-3;
    volume += cell_volume;
  }
  // Trilinear cells sharing their faces tile the cube, and the Gauss rule integrates
  // their Jacobians (degree ≤ 2 per direction) exactly: 1 up to rounding.
  EXPECT_NEAR(volume, 1.0, 1e-12);
  EXPECT_EQ(distorted, distortion != mesh::Distortion::None);
  EXPECT_EQ(cube.facets.size(), 6u * n * n);
  for (const mesh::BoundaryFacet& facet : cube.facets) {
    const auto axis = mesh::facet_normal_axis(cube, facet);
    ASSERT_TRUE(axis.has_value());
    EXPECT_EQ(*axis, facet.local_face / 2);
  }
}

INSTANTIATE_TEST_SUITE_P(OrdersAndDistortions, CubeMesh,
                         ::testing::Combine(::testing::Values(1, 2),
                                            ::testing::Values(mesh::Distortion::None,
                                                              mesh::Distortion::Smooth,
                                                              mesh::Distortion::Random)));

} // namespace
} // namespace formflow::testing
