// SPDX-License-Identifier: MIT
// The cell schedule (blocks that share no node, phase by phase) and the assembly it
// orders: the same tangent, force and coupling bit for bit on one thread and on several.
#include "formflow/assembly/cell_schedule.hpp"

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/core/parallel_tasks.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "support/newton_fixture.hpp"
#include "support/thread_cap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace formflow::testing {
namespace {

/// The plane channel 2 × 2 → 1 at h = 1/16: 1 536 cells, three blocks' worth.
mesh::Mesh<2> fine_channel() {
  return mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 1.0 / 16, 2);
}

void expect_valid(const mesh::Mesh<2>& mesh, const std::vector<Index>& loop,
                  const assembly::CellSchedule& schedule) {
  // Every loop cell exactly once.
  std::vector<Index> all;
  for (const auto& phase : schedule.phases)
    for (const auto& block : phase) all.insert(all.end(), block.begin(), block.end());
  std::vector<Index> sorted_loop = loop;
  std::sort(all.begin(), all.end());
  std::sort(sorted_loop.begin(), sorted_loop.end());
  EXPECT_EQ(all, sorted_loop);
  EXPECT_EQ(schedule.n_cells(), loop.size());
  std::vector<Index> position(static_cast<std::size_t>(mesh.n_cells()), -1);
  for (std::size_t k = 0; k < loop.size(); ++k) position[loop[k]] = static_cast<Index>(k);
  for (const auto& phase : schedule.phases) {
    // No node in two blocks of one phase.
    std::vector<int> owner(static_cast<std::size_t>(mesh.n_nodes()), -1);
    for (std::size_t b = 0; b < phase.size(); ++b) {
      EXPECT_FALSE(phase[b].empty());
      for (const Index cell : phase[b])
        for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
          int& node_owner = owner[mesh.cells(a, cell)];
          EXPECT_TRUE(node_owner == -1 || node_owner == static_cast<int>(b))
              << "node " << mesh.cells(a, cell) << " in blocks " << node_owner << " and " << b;
          node_owner = static_cast<int>(b);
        }
      // A block's cells in the loop's order.
      EXPECT_TRUE(std::is_sorted(phase[b].begin(), phase[b].end(),
                                 [&](Index x, Index y) { return position[x] < position[y]; }));
    }
  }
}

TEST(CellSchedule, BlocksOfAPhaseShareNoNodeAndEveryCellIsScheduledOnce) {
  const mesh::Mesh<2> mesh = fine_channel();
  std::vector<Index> loop(mesh.n_cells());
  std::iota(loop.begin(), loop.end(), 0);
  const assembly::CellSchedule schedule = assembly::make_cell_schedule(mesh, loop, 3);
  expect_valid(mesh, loop, schedule);
  ASSERT_GE(schedule.phases.size(), 2u);
  EXPECT_EQ(schedule.phases.front().size(), 3u);
  // Compact parts: most cells are in the first phase's blocks, few on the seams.
  std::size_t first = 0;
  for (const auto& block : schedule.phases.front()) first += block.size();
  EXPECT_GT(first, loop.size() * 8 / 10);
  EXPECT_EQ(schedule.phases.back().size(), 1u);
}

TEST(CellSchedule, AShuffledLoopOrderIsCutByPositionNotByNumber) {
  // A mesh numbered at random (as a remesher may): the parts are still compact.
  const mesh::Mesh<2> mesh = fine_channel();
  std::vector<Index> loop(mesh.n_cells());
  std::iota(loop.begin(), loop.end(), 0);
  std::shuffle(loop.begin(), loop.end(), std::mt19937(11));
  const assembly::CellSchedule schedule = assembly::make_cell_schedule(mesh, loop, 4);
  expect_valid(mesh, loop, schedule);
  std::size_t first = 0;
  for (const auto& block : schedule.phases.front()) first += block.size();
  EXPECT_GT(first, loop.size() * 8 / 10);
  // The same input, the same schedule.
  const assembly::CellSchedule again = assembly::make_cell_schedule(mesh, loop, 4);
  EXPECT_EQ(again.phases, schedule.phases);
}

TEST(CellSchedule, OneBlockIsTheLoopItself) {
  const mesh::Mesh<2> mesh = fine_channel();
  std::vector<Index> loop(mesh.n_cells());
  std::iota(loop.rbegin(), loop.rend(), 0);
  const assembly::CellSchedule schedule = assembly::make_cell_schedule(mesh, loop, 1);
  ASSERT_EQ(schedule.phases.size(), 1u);
  ASSERT_EQ(schedule.phases[0].size(), 1u);
  EXPECT_EQ(schedule.phases[0][0], loop);
}

struct Assembled {
  VectorX matrix_values, rhs, force, reaction_values;
  assembly::UnsymmetricTangent<2> coupling;
};

Assembled assemble(const SmallExtrusionIn<2>& extrusion, const std::string& threads) {
  const ThreadCap cap(threads);
  const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
  assembly::LinearSystem tangent = extrusion.problem->plan().make_system();
  Assembled out;
  extrusion.problem->assemble_newton(extrusion.u, thresholds, {}, out.force, &tangent,
                                     &out.coupling);
  out.matrix_values =
      Eigen::Map<const VectorX>(tangent.matrix.valuePtr(), tangent.matrix.nonZeros());
  out.rhs = tangent.rhs;
  out.reaction_values =
      Eigen::Map<const VectorX>(tangent.reaction_rows.valuePtr(), tangent.reaction_rows.nonZeros());
  return out;
}

TEST(CellSchedule, AssemblyIsTheSameBitForBitOnOneThreadAndOnSeveral) {
  // Regularised friction on Γ3 and the full-ε̇ form: every sink entry and the coupling's
  // points. Exact equality is the claim (the same additions in the same order), not a
  // tolerance. Several threads need a machine with several (CI has 2).
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one hardware thread";
  assembly::ProblemSettings settings;
  settings.law = sensitive_law();
  settings.viscous_strain = physics::ViscousStrain::Full;
  settings.friction.mu = 0.2;
  settings.friction.d_t = 0.05;
  settings.penalty.d = 0.1;
  settings.penalty.d_n = 0.1;
  const SmallExtrusionIn<2> extrusion(settings, fine_channel());
  const Assembled one = assemble(extrusion, "1");
  const Assembled several = assemble(extrusion, "2");
  EXPECT_EQ(one.matrix_values, several.matrix_values);
  EXPECT_EQ(one.rhs, several.rhs);
  EXPECT_EQ(one.force, several.force);
  EXPECT_EQ(one.reaction_values, several.reaction_values);
  EXPECT_EQ(one.coupling.cells, several.coupling.cells);
  EXPECT_EQ(one.coupling.coefficients, several.coupling.coefficients);
  EXPECT_EQ(one.coupling.rows, several.coupling.rows);
  EXPECT_FALSE(one.coupling.cells.empty());
  EXPECT_TRUE(one.coupling.has_friction);
  // N x by the blocks on one thread, on two, and in one sweep without the blocks: every
  // entry gets its points' terms in the same order, so the same bits.
  ASSERT_FALSE(several.coupling.phase_starts.empty());
  const Index n_free = extrusion.problem->plan().n_free();
  const VectorX x = random_vector(n_free, 17);
  const auto product = [&](const assembly::UnsymmetricTangent<2>& coupling, const char* threads) {
    const ThreadCap cap(threads);
    VectorX y = VectorX::Zero(n_free);
    extrusion.problem->apply_coupling(coupling, x, y);
    return y;
  };
  assembly::UnsymmetricTangent<2> one_sweep = several.coupling;
  one_sweep.phase_starts.clear();
  const VectorX reference = product(one_sweep, "2");
  EXPECT_EQ(product(several.coupling, "1"), reference);
  EXPECT_EQ(product(several.coupling, "2"), reference);
  EXPECT_GT(reference.norm(), 0.0);
}

} // namespace
} // namespace formflow::testing
