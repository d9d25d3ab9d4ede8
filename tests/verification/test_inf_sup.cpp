// SPDX-License-Identifier: MIT
// Remark 4.3 made visible: which velocity/pressure pairs keep β_h bounded.
#include "formflow/mesh/cube_mesh.hpp"
#include "formflow/mesh/tetrahedral_split.hpp"
#include "inf_sup_table.hpp"

#include <gtest/gtest.h>

namespace formflow::testing {
namespace {

enum Row {
  Q2P1disc,
  Q2P0,
  TaylorHood,
  Q2Q1disc,
  Q1P0,
  Q1P0Filtered,
  Q1Q1,
  P2PlusP1disc,
  P2P1,
  Mini,
  P2P1discWithoutBubbles
};

TEST(InfSup, StablePairsStayBoundedAndUnstableOnesDoNot) {
  const auto table = inf_sup_table({4, 8});
  // Stable pairs: only the constant pressure is in the null space, and β_h
  // does not fall as h halves (a 10 % margin for the pre-asymptotic rungs).
  for (Row row : {Q2P1disc, Q2P0, TaylorHood, P2PlusP1disc, P2P1, Mini}) {
    SCOPED_TRACE(inf_sup_pairs()[row].name);
    for (const auto& estimate : table[row]) EXPECT_EQ(estimate.n_null_modes, 1);
    EXPECT_GT(table[row][1].beta, 0.9 * table[row][0].beta);
    EXPECT_GT(table[row][1].beta, 0.05);
  }
  // Q1–P0: the checkerboard is a spurious null mode, and the rest decays with h.
  for (const auto& estimate : table[Q1P0]) EXPECT_GE(estimate.n_null_modes, 2);
  EXPECT_LT(table[Q1P0][1].beta, 0.75 * table[Q1P0][0].beta);
  // Q1–Q1 (equal order) has spurious pressure modes.
  for (const auto& estimate : table[Q1Q1]) EXPECT_GE(estimate.n_null_modes, 2);
  // Without its bubbles P2 cannot carry a discontinuous linear pressure: spurious modes
  // (why mesh.element = "P2" takes bubbles with P1disc, fem/element_choice.hpp).
  for (const auto& estimate : table[P2P1discWithoutBubbles]) EXPECT_GE(estimate.n_null_modes, 2);
  // The macro filter removes the checkerboard from the null space.
  for (const auto& estimate : table[Q1P0Filtered]) EXPECT_EQ(estimate.n_null_modes, 1);
}

TEST(InfSup, TetrahedralPairsStayBounded) {
  // The unit cube in n³ cubes, each cut into six tetrahedra (no-slip on its whole
  // boundary): β_h of the tetrahedral pairs at h = 1/2 and 1/4, with the criteria above.
  struct TetrahedralPair {
    const char* name;
    int order;
    bool bubbles;
    fem::PressureSpace space;
    bool stable;
  };
  const TetrahedralPair pairs[] = {
      {"P2+-P1disc", 2, true, fem::PressureSpace::P1disc, true},
      {"P2-P1 (Taylor-Hood)", 2, false, fem::PressureSpace::P1, true},
      {"P1b-P1 (MINI)", 1, true, fem::PressureSpace::P1, true},
      {"P2-P1disc (no bubbles)", 2, false, fem::PressureSpace::P1disc, false}};
  for (const TetrahedralPair& pair : pairs) {
    SCOPED_TRACE(pair.name);
    std::vector<InfSupEstimate> row;
    for (const int n : {2, 4}) {
      const mesh::Mesh<3> tetrahedra =
          mesh::split_into_tetrahedra(mesh::make_unit_cube_mesh(n, pair.order), pair.bubbles);
      row.push_back(inf_sup_constant(tetrahedra, pair.space));
      std::printf("| %s (tetrahedra) | h = 1/%d | %.4f (%d null) |\n", pair.name, n,
                  row.back().beta, row.back().n_null_modes);
    }
    if (!pair.stable) {
      for (const auto& estimate : row) EXPECT_GE(estimate.n_null_modes, 2);
      continue;
    }
    for (const auto& estimate : row) EXPECT_EQ(estimate.n_null_modes, 1);
    EXPECT_GT(row[1].beta, 0.9 * row[0].beta);
    EXPECT_GT(row[1].beta, 0.05);
  }
}

} // namespace
} // namespace formflow::testing
