// SPDX-License-Identifier: MIT
// Box meshes (uniform, smooth and random distortion) and mesh transformations.
#include "formflow/fem/cell_values.hpp"
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/mesh_transform.hpp"

#include <gtest/gtest.h>

namespace formflow::mesh {
namespace {

/// Sum of JxW over the mesh; false through `all_positive` if a cell is inverted.
Real area_of(const Mesh<2>& mesh, bool& all_positive) {
  const fem::QuadratureRule<2> rule = fem::gauss_rule<2>(3);
  fem::CellValues<2> values(mesh.order, rule);
  Real area = 0.0;
  all_positive = true;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    fem::CellValues<2>::Gradients nodes(2, mesh.nodes_per_cell());
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      nodes.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    all_positive &= values.reinit(nodes);
    for (int q = 0; q < values.n_points(); ++q) area += values.JxW(q);
  }
  return area;
}

TEST(BoxMesh, DistortedMeshesKeepTheBoxAndPositiveJacobians) {
  for (int order : {1, 2})
    for (Distortion kind : {Distortion::None, Distortion::Smooth, Distortion::Random}) {
      const Mesh<2> mesh = make_box_mesh(Point<2>(0.0, 0.0), Point<2>(2.0, 1.0), 8, 4, order,
                                         {kind, kind == Distortion::Smooth ? 0.1 : 0.24, 7});
      EXPECT_EQ(mesh.n_cells(), 32);
      EXPECT_EQ(mesh.n_nodes(), (8 * order + 1) * (4 * order + 1));
      EXPECT_EQ(mesh.facets.size(), 2u * (8 + 4));
      bool positive = false;
      // The boundary nodes do not move, so the area is exactly that of the box.
      EXPECT_NEAR(area_of(mesh, positive), 2.0, 1e-12);
      EXPECT_TRUE(positive);
    }
}

TEST(BoxMesh, RandomDistortionMovesInteriorNodesOffTheLattice) {
  const Mesh<2> uniform = make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), 4, 4, 1);
  const Mesh<2> random =
      make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), 4, 4, 1, {Distortion::Random, 0.2, 3});
  const Real moved = (random.nodes - uniform.nodes).colwise().norm().maxCoeff();
  EXPECT_GT(moved, 0.01);
  EXPECT_LE(moved, 0.2 * 0.25 * std::sqrt(2.0) + 1e-12);
}

TEST(MeshTransform, MirroringKeepsOrientationAndArea) {
  const Mesh<2> channel = make_channel_mesh(ChannelGeometry{}, 2.5, 2);
  bool positive = false;
  const Real area = area_of(channel, positive);
  for (int axis : {0, 1}) {
    const Mesh<2> image = mirrored(channel, axis);
    EXPECT_NEAR(area_of(image, positive), area, 1e-10);
    EXPECT_TRUE(positive) << "axis " << axis;
    const Mesh<2> twice = mirrored(image, axis);
    EXPECT_EQ(twice.cells, channel.cells);
    EXPECT_TRUE(twice.nodes.isApprox(channel.nodes));
  }
  const Mesh<2> moved = translated(channel, Point<2>(3.5, -1.25));
  EXPECT_NEAR(area_of(moved, positive), area, 1e-10);
  EXPECT_NEAR(moved.nodes(0, 0) - channel.nodes(0, 0), 3.5, 1e-15);
}

} // namespace
} // namespace formflow::mesh
