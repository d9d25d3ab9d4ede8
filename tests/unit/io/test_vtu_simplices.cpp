// SPDX-License-Identifier: MIT
// fields.vtu of triangles read back by VTK's own reader: types 5 and 22, node order,
// orientation, and bubble nodes kept as points but left out of the cells.
#include "formflow/io/vtu.hpp"
#include "formflow/mesh/simplex_split.hpp"
#include "support/approx.hpp"
#include "support/synthetic_run.hpp"
#include "support/vtk_reader.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace formflow::testing {
namespace {

/// `values` extended to `size` entries, the new ones zero (the bubble nodes).
VectorX padded(const VectorX& values, Index size) {
  VectorX out = VectorX::Zero(size);
  out.head(values.size()) = values;
  return out;
}

/// Each quadrilateral's cell value for both of its triangles (2c, 2c + 1).
VectorX doubled(const VectorX& values) {
  VectorX out(2 * values.size());
  for (Index c = 0; c < values.size(); ++c) out[2 * c] = out[2 * c + 1] = values[c];
  return out;
}

struct TriangleRun {
  mesh::Mesh<2> mesh;
  post::Fields fields;
};

TriangleRun triangle_run(int order, bool bubbles) {
  io::Case case_;
  mesh::Mesh<2> quadrilaterals;
  post::Results results;
  make_synthetic_run(order, 1.0, case_, quadrilaterals, results);
  TriangleRun run{mesh::split_into_triangles(quadrilaterals, bubbles), results.fields};
  const Index n = run.mesh.n_nodes();
  post::Fields& f = run.fields;
  f.velocity = padded(f.velocity, 2 * n);
  for (VectorX* nodal :
       {&f.equivalent_strain_rate, &f.hydrostatic_stress, &f.contact_pressure, &f.friction_stress})
    *nodal = padded(*nodal, n);
  f.cell_equivalent_strain_rate = doubled(f.cell_equivalent_strain_rate);
  f.cell_hydrostatic_stress = doubled(f.cell_hydrostatic_stress);
  f.cell_load_error.resize(0);
  return run;
}

double coordinate(const nlohmann::json& points, int id, int axis) {
  return points[id][axis].get<double>();
}

class VtuTriangles : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(VtuTriangles, TypesOrientationAndMidpointsAreVtks) {
  const auto [order, bubbles] = GetParam();
  const TriangleRun run = triangle_run(order, bubbles);
  const nlohmann::json seen =
      read_with_vtk(io::fields_vtu(run.mesh, run.fields),
                    "vtu_tri" + std::to_string(order) + (bubbles ? "b" : ""));
  ASSERT_TRUE(seen.contains("n_points"));
  ASSERT_EQ(seen["n_points"], run.mesh.n_nodes()); // bubble nodes are points too
  ASSERT_EQ(seen["n_cells"], run.mesh.n_cells());
  const int expected_type = order == 2 ? 22 : 5;
  const int expected_nodes = order == 2 ? 6 : 3;
  const auto& points = seen["points"];
  for (Index c = 0; c < run.mesh.n_cells(); ++c) {
    EXPECT_EQ(seen["cell_types"][c], expected_type);
    const auto& ids = seen["cells"][c];
    ASSERT_EQ(static_cast<int>(ids.size()), expected_nodes);
    double area = 0.0;
    for (int i = 0; i < 3; ++i) {
      const int a = ids[i].get<int>(), b = ids[(i + 1) % 3].get<int>();
      area += coordinate(points, a, 0) * coordinate(points, b, 1) -
              coordinate(points, b, 0) * coordinate(points, a, 1);
      EXPECT_EQ(a, run.mesh.cells(i, c)); // VTK's vertices are ours, in our order
    }
    EXPECT_GT(area, 0.0) << "cell " << c << " is not counter-clockwise";
    if (order != 2) continue;
    // VTK_QUADRATIC_TRIANGLE: points 3, 4, 5 are the midpoints of edges 0-1, 1-2, 2-0.
    for (int edge = 0; edge < 3; ++edge)
      for (int axis = 0; axis < 2; ++axis) {
        const double mid = 0.5 * (coordinate(points, ids[edge].get<int>(), axis) +
                                  coordinate(points, ids[(edge + 1) % 3].get<int>(), axis));
        EXPECT_TRUE(approx(coordinate(points, ids[3 + edge].get<int>(), axis), mid, 0.0, 1e-12))
            << "cell " << c << " edge " << edge;
      }
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, VtuTriangles,
                         ::testing::Combine(::testing::Values(1, 2), ::testing::Bool()),
                         [](const auto& info) {
                           return "P" + std::to_string(std::get<0>(info.param)) +
                                  (std::get<1>(info.param) ? "WithBubbles" : "");
                         });

TEST(VtkCellTypes, SimplicesAreTriangleAndTetraTypes) {
  using mesh::CellShape;
  EXPECT_EQ(io::vtk_cell_type({CellShape::Simplex, 1, true}, 2), 5);
  EXPECT_EQ(io::vtk_cell_type({CellShape::Simplex, 2, false}, 2), 22);
  EXPECT_EQ(io::vtk_cell_type({CellShape::Simplex, 1, false}, 3), 10);
  EXPECT_EQ(io::vtk_cell_type({CellShape::Simplex, 2, true}, 3), 24);
  EXPECT_EQ(io::vtk_node_order({CellShape::Simplex, 2, true}, 3).size(), 10u);
  EXPECT_EQ(io::vtk_node_order({CellShape::Cube, 2, false}, 3).size(), 27u);
}

} // namespace
} // namespace formflow::testing
