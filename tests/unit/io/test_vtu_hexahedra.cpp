// SPDX-License-Identifier: MIT
// fields.vtu of a solid (hexahedral) mesh read back by VTK: types, VTK's own node order, data.
#include "formflow/core/error.hpp"
#include "formflow/io/vtu.hpp"
#include "formflow/mesh/hex_box_mesh.hpp"
#include "support/vtk_reader.hpp"

#include <gtest/gtest.h>

#include <string>

namespace formflow::testing {

namespace {

using mesh::BoundaryLabel;
constexpr std::array<BoundaryLabel, 6> box_labels = {
    BoundaryLabel::Rear,     BoundaryLabel::Front,     BoundaryLabel::Symmetry,
    BoundaryLabel::FreeExit, BoundaryLabel::Container, BoundaryLabel::Container};

/// Fields with a different value at every node and cell, so a misplaced one shows:
/// velocity (x + 1, 2y − 1, 3z + 0.5), scalars from the node number.
post::Fields distinct_fields(const mesh::Mesh<3>& mesh) {
  post::Fields fields;
  fields.velocity.resize(3 * mesh.n_nodes());
  fields.equivalent_strain_rate.resize(mesh.n_nodes());
  for (Index n = 0; n < mesh.n_nodes(); ++n) {
    fields.velocity.segment<3>(3 * n) = Point<3>(
        mesh.nodes(0, n) + 1.0, 2.0 * mesh.nodes(1, n) - 1.0, 3.0 * mesh.nodes(2, n) + 0.5);
    fields.equivalent_strain_rate[n] = 0.5 + static_cast<Real>(n);
  }
  fields.hydrostatic_stress = -fields.equivalent_strain_rate;
  fields.contact_pressure = 2.0 * fields.equivalent_strain_rate;
  fields.friction_stress = 3.0 * fields.equivalent_strain_rate;
  fields.cell_equivalent_strain_rate = VectorX::LinSpaced(mesh.n_cells(), 1.0, 2.0);
  fields.cell_hydrostatic_stress = -fields.cell_equivalent_strain_rate;
  return fields;
}

class HexahedraReadBack : public ::testing::TestWithParam<int> {};

// One cell on the unit cube: its node at lattice position (i, j, k) sits at
// (i, j, k)/order, which is exactly VTK's parametric coordinate of the VTK
// point it is written as if (and only if) our order table matches VTK's.
TEST_P(HexahedraReadBack, NodeOrderIsVtksOwn) {
  const int order = GetParam();
  const mesh::Mesh<3> cube =
      mesh::make_hex_box_mesh(Point<3>::Zero(), Point<3>::Ones(), {1, 1, 1}, order, box_labels);
  const nlohmann::json seen =
      read_with_vtk(io::fields_vtu(cube, distinct_fields(cube)), "hex_q" + std::to_string(order));
  ASSERT_TRUE(seen.contains("n_cells"));
  const int type = order == 1 ? 12 : 29;
  ASSERT_EQ(seen["cell_types"][0], type);
  const auto& parametric = seen["parametric_coords"][std::to_string(type)];
  const auto& ids = seen["cells"][0];
  ASSERT_EQ(parametric.size(), order == 1 ? 8u : 27u);
  ASSERT_EQ(ids.size(), parametric.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(seen["points"][ids[k].get<int>()][axis].get<double>(),
                parametric[k][axis].get<double>())
          << "VTK point " << k << " axis " << axis;
}

TEST_P(HexahedraReadBack, BoxCountsTypesAndData) {
  const int order = GetParam();
  const mesh::Mesh<3> box = mesh::make_hex_box_mesh(
      Point<3>(0.0, 0.0, 0.0), Point<3>(3.0, 2.0, 1.0), {3, 2, 1}, order, box_labels);
  const post::Fields fields = distinct_fields(box);
  const nlohmann::json seen =
      read_with_vtk(io::fields_vtu(box, fields, solvers::StopReason::Diverged),
                    "hex_box_q" + std::to_string(order));
  ASSERT_TRUE(seen.contains("n_points"));
  ASSERT_EQ(seen["n_points"], box.n_nodes());
  ASSERT_EQ(seen["n_cells"], 6);
  for (const auto& type : seen["cell_types"]) EXPECT_EQ(type, order == 1 ? 12 : 29);
  EXPECT_EQ(seen["field_data"]["converged"]["values"][0], 0.0);
  const auto& velocity = seen["point_data"]["velocity"]["values"];
  const auto& rate = seen["point_data"]["equivalent_strain_rate"]["values"];
  for (Index n = 0; n < box.n_nodes(); ++n) {
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(seen["points"][n][axis].get<double>(), box.nodes(axis, n));
      EXPECT_EQ(velocity[3 * n + axis].get<double>(), fields.velocity[3 * n + axis]);
    }
    EXPECT_EQ(rate[n].get<double>(), fields.equivalent_strain_rate[n]);
  }
  for (Index c = 0; c < box.n_cells(); ++c)
    EXPECT_EQ(seen["cell_data"]["cell_id"]["values"][c].get<double>(), static_cast<double>(c));
}

INSTANTIATE_TEST_SUITE_P(Orders, HexahedraReadBack, ::testing::Values(1, 2));

TEST(HexahedraVtu, WrongVelocitySizeIsAnInternalError) {
  const mesh::Mesh<3> box =
      mesh::make_hex_box_mesh(Point<3>::Zero(), Point<3>::Ones(), {1, 1, 1}, 1, box_labels);
  post::Fields fields = distinct_fields(box);
  fields.velocity.conservativeResize(2 * box.n_nodes()); // a plane field on a solid mesh
  EXPECT_THROW(io::fields_vtu(box, fields), InternalError);
}

} // namespace

} // namespace formflow::testing
