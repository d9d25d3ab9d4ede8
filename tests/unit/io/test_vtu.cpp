// SPDX-License-Identifier: MIT
// fields.vtu read back by VTK's own reader: cell types, node order, points and fields.
#include "formflow/core/error.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/vtu.hpp"
#include "support/approx.hpp"
#include "support/synthetic_run.hpp"
#include "support/vtk_reader.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace formflow::testing {

namespace {

/// Twice the signed area of the polygon through `points` (> 0: counter-clockwise).
double twice_signed_area(const nlohmann::json& points, const nlohmann::json& ids, int count) {
  double area = 0.0;
  for (int i = 0; i < count; ++i) {
    const auto& a = points[ids[i].get<int>()];
    const auto& b = points[ids[(i + 1) % count].get<int>()];
    area += a[0].get<double>() * b[1].get<double>() - b[0].get<double>() * a[1].get<double>();
  }
  return area;
}

double coordinate(const nlohmann::json& points, int id, int axis) {
  return points[id][axis].get<double>();
}

class VtuReadBack : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    make_synthetic_run(GetParam(), 1.0, case_, mesh_, results_);
    seen_ =
        read_with_vtk(io::fields_vtu(mesh_, results_.fields), "vtu_q" + std::to_string(GetParam()));
    ASSERT_TRUE(seen_.contains("n_points"));
  }
  io::Case case_;
  mesh::Mesh<2> mesh_;
  post::Results results_;
  nlohmann::json seen_;
};

TEST_P(VtuReadBack, PointsCellsAndTypes) {
  ASSERT_EQ(seen_["n_points"], mesh_.n_nodes());
  ASSERT_EQ(seen_["n_cells"], mesh_.n_cells());
  const int expected_type = GetParam() == 2 ? 28 : 9;
  for (const auto& type : seen_["cell_types"]) EXPECT_EQ(type, expected_type);
  for (Index n = 0; n < mesh_.n_nodes(); ++n) {
    EXPECT_EQ(coordinate(seen_["points"], n, 0), mesh_.nodes(0, n));
    EXPECT_EQ(coordinate(seen_["points"], n, 1), mesh_.nodes(1, n));
    EXPECT_EQ(coordinate(seen_["points"], n, 2), 0.0);
  }
}

TEST_P(VtuReadBack, CellNodeOrderIsVtks) {
  const auto& points = seen_["points"];
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    const auto& ids = seen_["cells"][c];
    ASSERT_EQ(static_cast<int>(ids.size()), mesh_.nodes_per_cell());
    EXPECT_GT(twice_signed_area(points, ids, 4), 0.0) << "cell " << c << " corners not ccw";
    // Corner 0 is the lower-left one: VTK's first corner is our lexicographic node 0.
    EXPECT_EQ(ids[0], mesh_.cells(0, c));
    if (GetParam() != 2) continue;
    for (int axis = 0; axis < 2; ++axis) {
      // Points 4..7 are the mid-points of edges 0-1, 1-2, 2-3, 3-0; point 8 the centre.
      for (int edge = 0; edge < 4; ++edge) {
        const double mid = 0.5 * (coordinate(points, ids[edge], axis) +
                                  coordinate(points, ids[(edge + 1) % 4], axis));
        EXPECT_TRUE(approx(coordinate(points, ids[4 + edge], axis), mid, 0.0, 1e-12))
            << "cell " << c << " edge " << edge;
      }
      double centre = 0.0;
      for (int corner = 0; corner < 4; ++corner)
        centre += 0.25 * coordinate(points, ids[corner], axis);
      EXPECT_TRUE(approx(coordinate(points, ids[8], axis), centre, 0.0, 1e-12)) << "cell " << c;
    }
  }
}

TEST_P(VtuReadBack, PointDataMatchesTheFields) {
  const auto& data = seen_["point_data"];
  const auto& fields = results_.fields;
  ASSERT_EQ(data["velocity"]["components"], 3);
  const auto& velocity = data["velocity"]["values"];
  for (Index n = 0; n < mesh_.n_nodes(); ++n) {
    EXPECT_EQ(velocity[3 * n].get<double>(), fields.velocity[2 * n]) << "node " << n;
    EXPECT_EQ(velocity[3 * n + 1].get<double>(), fields.velocity[2 * n + 1]) << "node " << n;
    EXPECT_EQ(velocity[3 * n + 2].get<double>(), 0.0);
    // Shortest round-trip formatting: the reader gets the same doubles back.
    EXPECT_EQ(data["equivalent_strain_rate"]["values"][n].get<double>(),
              fields.equivalent_strain_rate[n]);
    EXPECT_EQ(data["hydrostatic_stress"]["values"][n].get<double>(), fields.hydrostatic_stress[n]);
    EXPECT_EQ(data["hydrostatic_pressure"]["values"][n].get<double>(),
              -fields.hydrostatic_stress[n]);
    EXPECT_EQ(data["contact_pressure"]["values"][n].get<double>(), fields.contact_pressure[n]);
    EXPECT_EQ(data["friction_stress"]["values"][n].get<double>(), fields.friction_stress[n]);
  }
  // The synthetic exit flow is 2 and the dead zone still: a sanity check on the data itself.
  EXPECT_GT(*std::max_element(velocity.begin(), velocity.end()), 1.9);
}

TEST_P(VtuReadBack, CellDataMatchesTheFields) {
  const auto& data = seen_["cell_data"];
  const auto& fields = results_.fields;
  for (Index c = 0; c < mesh_.n_cells(); ++c) {
    EXPECT_EQ(data["cell_id"]["values"][c].get<double>(), c);
    EXPECT_EQ(data["equivalent_strain_rate"]["values"][c].get<double>(),
              fields.cell_equivalent_strain_rate[c]);
    EXPECT_EQ(data["hydrostatic_stress"]["values"][c].get<double>(),
              fields.cell_hydrostatic_stress[c]);
    EXPECT_EQ(data["hydrostatic_pressure"]["values"][c].get<double>(),
              -fields.cell_hydrostatic_stress[c]);
  }
}

TEST_P(VtuReadBack, FieldDataSaysWhetherTheRunConverged) {
  const auto& converged = seen_["field_data"]["converged"];
  EXPECT_EQ(converged["values"], nlohmann::json::array({1.0}));
  const std::string text =
      io::fields_vtu(mesh_, results_.fields, solvers::StopReason::MaxIterations);
  EXPECT_NE(text.find("<!-- NOT CONVERGED (max_iterations)"), std::string::npos);
  const auto unconverged = read_with_vtk(text, "vtu_unconverged_q" + std::to_string(GetParam()));
  EXPECT_EQ(unconverged["field_data"]["converged"]["values"], nlohmann::json::array({0.0}));
  // The fields themselves are written all the same: the last iterate, marked.
  EXPECT_EQ(unconverged["n_points"], mesh_.n_nodes());
}

INSTANTIATE_TEST_SUITE_P(Orders, VtuReadBack, ::testing::Values(1, 2),
                         [](const auto& info) { return "Q" + std::to_string(info.param); });

TEST(VtkNodeOrder, CornersCounterClockwiseThenEdgesThenCentre) {
  // Reference coordinates of VTK's quad-9 positions, independent of our mapping.
  const std::array<std::array<double, 2>, 9> vtk_q2 = {
      {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}}};
  const auto order = io::vtk_node_order(2);
  ASSERT_EQ(order.size(), 9u);
  for (std::size_t k = 0; k < 9; ++k) {
    const Point<2> xi = fem::reference_node<2>(2, order[k]);
    EXPECT_EQ(xi[0], vtk_q2[k][0]) << "VTK position " << k;
    EXPECT_EQ(xi[1], vtk_q2[k][1]) << "VTK position " << k;
  }
  const auto order_q1 = io::vtk_node_order(1);
  ASSERT_EQ(order_q1.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const Point<2> xi = fem::reference_node<2>(1, order_q1[k]);
    EXPECT_EQ(xi[0], vtk_q2[k][0]);
    EXPECT_EQ(xi[1], vtk_q2[k][1]);
  }
  EXPECT_EQ(io::vtk_cell_type(1), 9);
  EXPECT_EQ(io::vtk_cell_type(2), 28);
}

TEST(VtuGuards, NonFiniteOrMissizedFieldsThrow) {
  io::Case case_;
  mesh::Mesh<2> mesh;
  post::Results results;
  make_synthetic_run(2, 1.0, case_, mesh, results);
  post::Fields fields = results.fields;
  fields.friction_stress[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(io::fields_vtu(mesh, fields), InternalError);
  fields = results.fields;
  fields.velocity.conservativeResize(fields.velocity.size() - 2);
  EXPECT_THROW(io::fields_vtu(mesh, fields), InternalError);
  fields = results.fields;
  fields.cell_hydrostatic_stress[0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(io::fields_vtu(mesh, fields), InternalError);
  EXPECT_NO_THROW(io::fields_vtu(mesh, results.fields));
}

} // namespace
} // namespace formflow::testing
