// SPDX-License-Identifier: MIT
// ScatterPlan against a dense reference with explicit elimination of the prescribed dofs.
#include "formflow/assembly/sparsity.hpp"

#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace formflow::testing {
namespace {

using assembly::BlockDofs;
using assembly::LinearSystem;
using assembly::ScatterPlan;

// Each global entry is a sum of ≤ 4 local O(1) entries (shared nodes), rhs
// entries sums of ≤ 40 O(1) products: 1e-13 absolute is round-off.
constexpr double scatter_roundoff = 1e-13;

/// The tiny channel: container 2×2, exit 2×1, unit cells.
mesh::Mesh<2> tiny_mesh(int order) {
  return mesh::make_channel_mesh(mesh::ChannelGeometry{2, 2, 1, 2}, 1.0, order);
}

/// Cell blocks plus, to exercise unequal block sizes, one block per boundary facet.
BlockDofs blocks_of(const mesh::Mesh<2>& m) {
  BlockDofs blocks;
  for (Index c = 0; c < m.n_cells(); ++c) blocks.add(fem::dofs_of_nodes<2>(m.cells.col(c)));
  for (const mesh::BoundaryFacet& facet : m.facets) {
    std::vector<Index> nodes;
    for (int local : mesh::face_local_nodes<2>(m.nodes_per_side(), facet.local_face))
      nodes.push_back(m.cells(local, facet.cell));
    blocks.add(fem::dofs_of_nodes<2>(nodes));
  }
  return blocks;
}

/// About one dof in five prescribed, spread over the mesh.
std::vector<bool> some_prescribed(Index n_dofs) {
  std::vector<bool> prescribed(n_dofs);
  for (Index dof = 0; dof < n_dofs; ++dof) prescribed[dof] = (dof * 7) % 5 == 0;
  return prescribed;
}

MatrixX random_symmetric(int n, std::mt19937& generator) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  MatrixX m(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m(i, j) = uniform(generator);
  return 0.5 * (m + m.transpose());
}

class ScatterPlanTest : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    mesh_ = tiny_mesh(GetParam());
    n_dofs_ = mesh_.n_nodes() * 2;
    blocks_ = blocks_of(mesh_);
    prescribed_ = some_prescribed(n_dofs_);
    std::mt19937 generator(42 + GetParam());
    std::uniform_real_distribution<double> uniform(-2.0, 2.0);
    values_ = VectorX::Zero(n_dofs_);
    for (Index dof = 0; dof < n_dofs_; ++dof)
      if (prescribed_[dof]) values_[dof] = uniform(generator);
    for (Index b = 0; b < blocks_.n_blocks(); ++b)
      locals_.push_back(random_symmetric(blocks_.block_size(b), generator));
    // The dense reference: K = Σ_blocks Pᵀ K_e P, written out entry by entry.
    full_ = MatrixX::Zero(n_dofs_, n_dofs_);
    for (Index b = 0; b < blocks_.n_blocks(); ++b) {
      const Index* dofs = blocks_.dofs.data() + blocks_.offsets[b];
      for (int i = 0; i < blocks_.block_size(b); ++i)
        for (int j = 0; j < blocks_.block_size(b); ++j) full_(dofs[i], dofs[j]) += locals_[b](i, j);
    }
  }

  void scatter_all(const ScatterPlan& plan, LinearSystem& system) const {
    for (Index b = 0; b < blocks_.n_blocks(); ++b) plan.scatter(b, locals_[b], values_, system);
  }

  /// Free dofs in the order of their free index, checked to be a bijection.
  std::vector<Index> free_dofs(const ScatterPlan& plan) const {
    std::vector<Index> dofs(plan.n_free(), -1);
    for (Index dof = 0; dof < n_dofs_; ++dof) {
      const Index i = plan.free_index(dof);
      EXPECT_EQ(i < 0, static_cast<bool>(prescribed_[dof])) << dof;
      if (i < 0) continue;
      EXPECT_LT(i, plan.n_free());
      EXPECT_EQ(dofs[i], -1) << "free index used twice";
      dofs[i] = dof;
    }
    return dofs;
  }
  std::vector<Index> prescribed_dofs(const ScatterPlan& plan) const {
    std::vector<Index> dofs(plan.n_prescribed(), -1);
    for (Index dof = 0; dof < n_dofs_; ++dof) {
      const Index i = plan.prescribed_index(dof);
      EXPECT_EQ(i >= 0, static_cast<bool>(prescribed_[dof])) << dof;
      if (i < 0) continue;
      EXPECT_EQ(dofs[i], -1) << "prescribed index used twice";
      dofs[i] = dof;
    }
    return dofs;
  }

  mesh::Mesh<2> mesh_;
  Index n_dofs_ = 0;
  BlockDofs blocks_;
  std::vector<bool> prescribed_;
  VectorX values_;
  std::vector<MatrixX> locals_;
  MatrixX full_;
};

TEST_P(ScatterPlanTest, CountsFollowThePrescribedMask) {
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  Index n_prescribed = 0;
  for (bool p : prescribed_) n_prescribed += p;
  EXPECT_EQ(plan.n_dofs(), n_dofs_);
  EXPECT_EQ(plan.n_prescribed(), n_prescribed);
  EXPECT_EQ(plan.n_free(), n_dofs_ - n_prescribed);
  EXPECT_GT(n_prescribed, 0);
}

TEST_P(ScatterPlanTest, FreeBlockIsTheLowerTriangleOfTheDenseReference) {
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  LinearSystem system = plan.make_system();
  scatter_all(plan, system);
  const std::vector<Index> free = free_dofs(plan);
  const MatrixX stored = MatrixX(system.matrix);
  ASSERT_EQ(stored.rows(), plan.n_free());
  ASSERT_EQ(stored.cols(), plan.n_free());
  for (Index i = 0; i < plan.n_free(); ++i)
    for (Index j = 0; j < plan.n_free(); ++j) {
      const double expected = i >= j ? full_(free[i], free[j]) : 0.0; // upper triangle not stored
      EXPECT_TRUE(approx(stored(i, j), expected, 0.0, scatter_roundoff))
          << "K_ff(" << i << ", " << j << ")";
    }
}

TEST_P(ScatterPlanTest, RightHandSideMovesThePrescribedColumns) {
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  LinearSystem system = plan.make_system();
  scatter_all(plan, system);
  const std::vector<Index> free = free_dofs(plan);
  // F_f = −K_fc u_c; values_ is zero on the free dofs, so K_fc u_c = (K values_)_f.
  const VectorX k_u = full_ * values_;
  for (Index i = 0; i < plan.n_free(); ++i)
    EXPECT_TRUE(approx(system.rhs[i], -k_u[free[i]], 0.0, scatter_roundoff)) << "F_f(" << i << ")";
}

TEST_P(ScatterPlanTest, ReactionRowsAreThePrescribedRowsOfTheFullMatrix) {
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  LinearSystem system = plan.make_system();
  scatter_all(plan, system);
  const std::vector<Index> prescribed = prescribed_dofs(plan);
  const MatrixX rows = MatrixX(system.reaction_rows);
  ASSERT_EQ(rows.rows(), plan.n_prescribed());
  ASSERT_EQ(rows.cols(), n_dofs_);
  for (Index r = 0; r < plan.n_prescribed(); ++r)
    for (Index dof = 0; dof < n_dofs_; ++dof)
      EXPECT_TRUE(approx(rows(r, dof), full_(prescribed[r], dof), 0.0, scatter_roundoff))
          << r << ", " << dof;
}

TEST_P(ScatterPlanTest, EliminatedSystemReproducesTheFullProduct) {
  // For any free values u_f: K_ff u_f − F_f = (K u)_f with u = expand(u_f, u_c),
  // and reaction_rows·u = (K u)_c. Uses the symmetric view of the stored triangle.
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  LinearSystem system = plan.make_system();
  scatter_all(plan, system);
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX free_values(plan.n_free());
  for (Index i = 0; i < plan.n_free(); ++i) free_values[i] = uniform(generator);
  const VectorX u = plan.expand(free_values, values_);
  const VectorX k_u = full_ * u;
  const VectorX lhs = system.matrix.selfadjointView<Eigen::Lower>() * free_values - system.rhs;
  const VectorX reactions = system.reaction_rows * u;
  for (Index dof = 0; dof < n_dofs_; ++dof) {
    const double actual =
        prescribed_[dof] ? reactions[plan.prescribed_index(dof)] : lhs[plan.free_index(dof)];
    EXPECT_TRUE(approx(actual, k_u[dof], 0.0, scatter_roundoff)) << dof;
  }
}

TEST_P(ScatterPlanTest, ScatterAccumulatesAndClearKeepsThePattern) {
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  LinearSystem once = plan.make_system(), twice = plan.make_system();
  scatter_all(plan, once);
  scatter_all(plan, twice);
  scatter_all(plan, twice);
  EXPECT_TRUE(approx((MatrixX(twice.matrix) - 2 * MatrixX(once.matrix)).norm(), 0.0, 0.0,
                     scatter_roundoff));
  EXPECT_TRUE(approx((twice.rhs - 2 * once.rhs).norm(), 0.0, 0.0, scatter_roundoff));
  const Index non_zeros = twice.matrix.nonZeros();
  ScatterPlan::clear(twice);
  EXPECT_EQ(twice.matrix.nonZeros(), non_zeros);
  EXPECT_EQ(MatrixX(twice.matrix).norm(), 0.0);
  EXPECT_EQ(MatrixX(twice.reaction_rows).norm(), 0.0);
  EXPECT_EQ(twice.rhs.norm(), 0.0);
  // After clearing, one more pass equals a single fresh assembly exactly.
  scatter_all(plan, twice);
  EXPECT_EQ(MatrixX(twice.matrix), MatrixX(once.matrix));
  EXPECT_EQ(twice.rhs, once.rhs);
}

TEST_P(ScatterPlanTest, PatternHoldsOnlyCoupledPairs) {
  // Only pairs of dofs sharing a block appear (lower triangle): no dense fill.
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  const LinearSystem system = plan.make_system();
  const std::vector<Index> free = free_dofs(plan);
  MatrixX coupled = MatrixX::Zero(n_dofs_, n_dofs_);
  for (Index b = 0; b < blocks_.n_blocks(); ++b) {
    const Index* dofs = blocks_.dofs.data() + blocks_.offsets[b];
    for (int i = 0; i < blocks_.block_size(b); ++i)
      for (int j = 0; j < blocks_.block_size(b); ++j) coupled(dofs[i], dofs[j]) = 1;
  }
  Index expected = 0;
  for (Index i = 0; i < plan.n_free(); ++i)
    for (Index j = 0; j <= i; ++j) expected += coupled(free[i], free[j]) != 0;
  EXPECT_EQ(system.matrix.nonZeros(), expected);
}

TEST_P(ScatterPlanTest, ExpandRoundTrips) {
  const ScatterPlan plan(n_dofs_, prescribed_, blocks_);
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX full(n_dofs_);
  for (Index dof = 0; dof < n_dofs_; ++dof) full[dof] = uniform(generator);
  VectorX free_part(plan.n_free());
  VectorX prescribed_part =
      VectorX::Constant(n_dofs_, 99.0); // junk where free: must be overwritten
  for (Index dof = 0; dof < n_dofs_; ++dof)
    (prescribed_[dof] ? prescribed_part[dof] : free_part[plan.free_index(dof)]) = full[dof];
  EXPECT_EQ(plan.expand(free_part, prescribed_part), full);
}

INSTANTIATE_TEST_SUITE_P(Orders, ScatterPlanTest, ::testing::Values(1, 2),
                         [](const auto& info) { return info.param == 1 ? "Q1" : "Q2"; });

TEST(ScatterPlan, NothingPrescribedGivesTheWholeLowerTriangleAndNoReactions) {
  const mesh::Mesh<2> m = tiny_mesh(1);
  const Index n_dofs = m.n_nodes() * 2;
  BlockDofs blocks;
  for (Index c = 0; c < m.n_cells(); ++c) blocks.add(fem::dofs_of_nodes<2>(m.cells.col(c)));
  const ScatterPlan plan(n_dofs, std::vector<bool>(n_dofs, false), blocks);
  EXPECT_EQ(plan.n_free(), n_dofs);
  LinearSystem system = plan.make_system();
  EXPECT_EQ(system.reaction_rows.rows(), 0);
  const MatrixX ones = MatrixX::Ones(8, 8);
  for (Index c = 0; c < m.n_cells(); ++c) plan.scatter(c, ones, VectorX::Zero(n_dofs), system);
  // The diagonal of a node's dof counts the cells around it: the corner node
  // at the origin lies in one cell, the node at (1, 1) in four.
  const MatrixX stored = MatrixX(system.matrix);
  auto node_at = [&](double x, double y) {
    for (Index n = 0; n < m.n_nodes(); ++n)
      if (m.nodes(0, n) == x && m.nodes(1, n) == y) return n;
    return Index{-1};
  };
  const Index corner = node_at(0.0, 0.0), centre = node_at(1.0, 1.0);
  ASSERT_GE(corner, 0);
  ASSERT_GE(centre, 0);
  const Index corner_dof = plan.free_index(fem::dof_of<2>(corner, 0));
  const Index centre_dof = plan.free_index(fem::dof_of<2>(centre, 1));
  EXPECT_EQ(stored(corner_dof, corner_dof), 1.0);
  EXPECT_EQ(stored(centre_dof, centre_dof), 4.0);
  EXPECT_EQ(system.rhs.norm(), 0.0);
}

} // namespace
} // namespace formflow::testing
