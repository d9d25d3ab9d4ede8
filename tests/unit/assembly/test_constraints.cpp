// SPDX-License-Identifier: MIT
// Dirichlet data of extrusion (sliding, sticking ram) and drawing, checked node by node by
// coordinates.
#include "formflow/assembly/constraints.hpp"

#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/extruded_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace formflow::testing {
namespace {

using physics::ProcessType;
using physics::RamCondition;

// Geometry {Lc = 4, H_in = 4, H_out = 2, Le = 4}, unit cells: rear x = 0,
// front x = 8, symmetry y = 0. Generator coordinates are exact multiples here.
const mesh::ChannelGeometry geometry{4, 4, 2, 4};
constexpr double speed = 1.7;

bool at(double value, double target) {
  return std::abs(value - target) < 1e-12;
}

physics::Process process(ProcessType type, RamCondition ram) {
  physics::Process p;
  p.type = type;
  p.speed = speed;
  p.ram = ram;
  return p;
}

struct Expected {
  bool x_prescribed, y_prescribed;
  double x_value;
};

/// What SPEC §1/§4 asks at a node, from its coordinates alone.
Expected expected_at(const Point<2>& p, ProcessType type, RamCondition ram) {
  const bool rear = at(p.x(), 0.0), front = at(p.x(), 8.0), symmetry = at(p.y(), 0.0);
  const bool driven = type == ProcessType::Extrusion ? rear : front;
  const bool sticking = type == ProcessType::Extrusion && ram == RamCondition::Sticking && rear;
  return {driven, symmetry || sticking, driven ? speed : 0.0};
}

class ProcessConstraints
    : public ::testing::TestWithParam<std::tuple<int, ProcessType, RamCondition>> {};

TEST_P(ProcessConstraints, PrescribeExactlyTheDrivenEndAndTheSymmetryPlane) {
  const auto [order, type, ram] = GetParam();
  const mesh::Mesh<2> m = mesh::make_channel_mesh(geometry, 1.0, order);
  const assembly::DirichletConstraints c =
      assembly::make_process_constraints<2>(m, process(type, ram));
  ASSERT_EQ(static_cast<Index>(c.prescribed.size()), 2 * m.n_nodes());
  ASSERT_EQ(c.values.size(), 2 * m.n_nodes());
  Index n_driven = 0;
  for (Index node = 0; node < m.n_nodes(); ++node) {
    const Expected e = expected_at(m.nodes.col(node), type, ram);
    const Index x_dof = fem::dof_of<2>(node, 0), y_dof = fem::dof_of<2>(node, 1);
    EXPECT_EQ(c.prescribed[x_dof], e.x_prescribed) << "u_x at " << m.nodes.col(node).transpose();
    EXPECT_EQ(c.prescribed[y_dof], e.y_prescribed) << "u_y at " << m.nodes.col(node).transpose();
    if (e.x_prescribed) {
      EXPECT_EQ(c.values[x_dof], e.x_value);
    }
    if (e.y_prescribed) {
      EXPECT_EQ(c.values[y_dof], 0.0);
    }
    n_driven += e.x_prescribed;
  }
  // Driven dofs: the u_x of each node on the driven end, once each.
  EXPECT_EQ(static_cast<Index>(c.driven_dofs.size()), n_driven);
  for (Index dof : c.driven_dofs) {
    EXPECT_EQ(dof % 2, 0) << "driven dofs are x components";
    EXPECT_TRUE(c.prescribed[dof]);
    EXPECT_EQ(c.values[dof], speed);
  }
  std::vector<Index> sorted = c.driven_dofs;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  EXPECT_EQ(c.driven_label, type == ProcessType::Extrusion ? mesh::BoundaryLabel::Rear
                                                           : mesh::BoundaryLabel::Front);
  // Lattice nodes on the driven end: o·4 + 1 on the rear (height 4), o·2 + 1 on the front.
  EXPECT_EQ(n_driven, type == ProcessType::Extrusion ? 4 * order + 1 : 2 * order + 1);
}

INSTANTIATE_TEST_SUITE_P(
    Processes, ProcessConstraints,
    ::testing::Combine(::testing::Values(1, 2),
                       ::testing::Values(ProcessType::Extrusion, ProcessType::Drawing),
                       ::testing::Values(RamCondition::Sliding, RamCondition::Sticking)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) == 1 ? "Q1" : "Q2") +
             (std::get<1>(info.param) == ProcessType::Extrusion ? "Extrusion" : "Drawing") +
             (std::get<2>(info.param) == RamCondition::Sliding ? "Sliding" : "Sticking");
    });

/// The solid slab: the channel above extruded over z ∈ [0, 1] in two layers, both z
/// faces symmetry planes. u_N = 0 there is u_z = 0, on y = 0 it is u_y = 0 (both on the
/// edges y = 0, z ∈ {0, 1}); a sticking ram holds u_y and u_z.
class SlabConstraints
    : public ::testing::TestWithParam<std::tuple<int, ProcessType, RamCondition>> {};

TEST_P(SlabConstraints, FixTheNormalComponentOnEachSymmetryPlaneAndTheDrivenEnd) {
  const auto [order, type, ram] = GetParam();
  const mesh::Mesh<3> slab = mesh::extrude_mesh(mesh::make_channel_mesh(geometry, 1.0, order), 1.0,
                                                2, mesh::BoundaryLabel::Symmetry);
  const assembly::DirichletConstraints c =
      assembly::make_process_constraints<3>(slab, process(type, ram));
  ASSERT_EQ(static_cast<Index>(c.prescribed.size()), 3 * slab.n_nodes());
  Index n_driven = 0;
  for (Index node = 0; node < slab.n_nodes(); ++node) {
    const Point<3> p = slab.nodes.col(node);
    const Expected plane = expected_at(Point<2>(p.x(), p.y()), type, ram);
    const bool sticking =
        type == ProcessType::Extrusion && ram == RamCondition::Sticking && at(p.x(), 0.0);
    const bool z_prescribed = at(p.z(), 0.0) || at(p.z(), 1.0) || sticking;
    const std::array<bool, 3> expected = {plane.x_prescribed, plane.y_prescribed, z_prescribed};
    for (int axis = 0; axis < 3; ++axis) {
      const Index dof = fem::dof_of<3>(node, axis);
      EXPECT_EQ(c.prescribed[dof], expected[axis]) << "u_" << axis << " at " << p.transpose();
      if (expected[axis]) {
        EXPECT_EQ(c.values[dof], axis == 0 ? plane.x_value : 0.0);
      }
    }
    n_driven += plane.x_prescribed;
  }
  EXPECT_EQ(static_cast<Index>(c.driven_dofs.size()), n_driven);
  for (Index dof : c.driven_dofs) EXPECT_EQ(dof % 3, 0) << "driven dofs are x components";
  // Driven end nodes: its plane lattice line times 2·order + 1 levels in z.
  EXPECT_EQ(n_driven,
            (type == ProcessType::Extrusion ? 4 * order + 1 : 2 * order + 1) * (2 * order + 1));
}

INSTANTIATE_TEST_SUITE_P(
    Processes, SlabConstraints,
    ::testing::Combine(::testing::Values(1, 2),
                       ::testing::Values(ProcessType::Extrusion, ProcessType::Drawing),
                       ::testing::Values(RamCondition::Sliding, RamCondition::Sticking)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) == 1 ? "Q1" : "Q2") +
             (std::get<1>(info.param) == ProcessType::Extrusion ? "Extrusion" : "Drawing") +
             (std::get<2>(info.param) == RamCondition::Sliding ? "Sliding" : "Sticking");
    });

TEST(ProcessConstraints, SlidingRamLeavesRearVerticalVelocityFreeExceptOnTheAxis) {
  // The paper's ram (σ_T = 0): u_y is free on Γ1 except at the symmetry corner.
  const mesh::Mesh<2> m = mesh::make_channel_mesh(geometry, 1.0, 1);
  const auto c = assembly::make_process_constraints<2>(
      m, process(ProcessType::Extrusion, RamCondition::Sliding));
  Index free_on_rear = 0;
  for (Index node = 0; node < m.n_nodes(); ++node)
    if (at(m.nodes(0, node), 0.0) && !c.prescribed[fem::dof_of<2>(node, 1)]) ++free_on_rear;
  EXPECT_EQ(free_on_rear, 4); // y = 1, 2, 3, 4
}

TEST(NodesOn, AscendingUniqueAndOnTheirLine) {
  for (int order : {1, 2}) {
    const mesh::Mesh<2> m = mesh::make_channel_mesh(geometry, 1.0, order);
    const std::vector<Index> symmetry = assembly::nodes_on<2>(m, mesh::BoundaryLabel::Symmetry);
    EXPECT_EQ(static_cast<Index>(symmetry.size()), 8 * order + 1); // x = 0 … 8
    EXPECT_TRUE(std::is_sorted(symmetry.begin(), symmetry.end()));
    EXPECT_TRUE(std::adjacent_find(symmetry.begin(), symmetry.end()) == symmetry.end());
    for (Index node : symmetry) EXPECT_TRUE(at(m.nodes(1, node), 0.0));
    const std::vector<Index> die = assembly::nodes_on<2>(m, mesh::BoundaryLabel::Die);
    EXPECT_EQ(static_cast<Index>(die.size()), 2 * order + 1); // y = 2 … 4 on x = 4
    for (Index node : die) {
      EXPECT_TRUE(at(m.nodes(0, node), 4.0));
      EXPECT_GE(m.nodes(1, node), 2.0 - 1e-12);
    }
    EXPECT_TRUE(assembly::nodes_on<2>(m, mesh::BoundaryLabel::FreeEntry).empty());
  }
}

} // namespace
} // namespace formflow::testing
