// SPDX-License-Identifier: MIT
// solvers::petsc::share_pattern: on several ranks each share goes to PETSc in the contact
// frames and the node layout through a ValueMap on its own pattern. The shares' laid-out
// values must add up to the whole system's, and a share must hold the decoupled slot of
// the nodes it touches only (so that the lowest rank touching a node owns all its rows).
#include "formflow/solvers/petsc/value_map.hpp"

#include "formflow/assembly/local_frame.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace formflow {
namespace {

// 2D, four mesh nodes: node 0 free, node 1 with its x prescribed, node 2 prescribed
// whole, node 3 free; two pressure rows. Velocity rows 0..4 are the mesh dofs 0, 1, 3,
// 6, 7; the layout's slot is node 1's x.
const std::vector<Index> share_dofs = {0, 1, 3, 6, 7};
constexpr Index share_rows = 7, share_velocity = 5;

void set_symmetric(MatrixX& k, Index i, Index j, Real value) {
  k(i, j) = k(j, i) = value;
}

/// Rank A's cells: nodes 0 and 3 (velocity rows 0, 3, 4) and pressure row 6.
MatrixX share_a() {
  MatrixX k = MatrixX::Zero(share_rows, share_rows);
  k(0, 0) = 2.0;
  k(3, 3) = 7.0;
  k(4, 4) = 8.0;
  k(6, 6) = -1e-3;
  set_symmetric(k, 0, 3, 0.45);
  set_symmetric(k, 3, 4, -0.7);
  set_symmetric(k, 6, 3, 0.25);
  set_symmetric(k, 6, 4, -0.15);
  return k;
}

/// Rank B's cells: nodes 0 and 1 (velocity rows 0, 1, 2) and pressure row 5.
MatrixX share_b() {
  MatrixX k = MatrixX::Zero(share_rows, share_rows);
  k(0, 0) = 4.0;
  k(1, 1) = 5.0;
  k(2, 2) = 6.0;
  k(5, 5) = -1e-3;
  set_symmetric(k, 0, 1, -1.0);
  set_symmetric(k, 1, 2, -0.5);
  set_symmetric(k, 5, 0, 0.3);
  set_symmetric(k, 5, 2, 0.2);
  return k;
}

assembly::SparseMatrix stored(const MatrixX& dense, bool lower_only) {
  assembly::SparseMatrix sparse =
      (lower_only ? MatrixX(dense.triangularView<Eigen::Lower>()) : dense).sparseView();
  sparse.makeCompressed();
  return sparse;
}

/// One frame on node 3's rows 3 and 4, a rotation by 0.4 rad.
assembly::SparseMatrix share_frames() {
  assembly::LocalFrame frame;
  frame.rows = {3, 4};
  frame.basis.resize(2, 2);
  const Real c = std::cos(0.4), s = std::sin(0.4);
  frame.basis << c, -s, s, c;
  const std::vector<assembly::LocalFrame> frames = {frame};
  return assembly::frame_matrix(frames, share_rows);
}

/// The laid-out values a map gives on `pattern`, scattered into a dense matrix.
MatrixX laid_out(const assembly::SparseMatrix& input, bool lower_only,
                 const assembly::SparseMatrix& frames,
                 const solvers::petsc::NodeBlockLayout& layout,
                 const solvers::petsc::CsrPattern& pattern) {
  const solvers::petsc::ValueMap map(input, lower_only, frames, layout, pattern.outer,
                                     pattern.inner, share_velocity);
  std::vector<Real> values(pattern.inner.size());
  map.fill(input, values);
  const Index n = layout.n_embedded();
  MatrixX dense = MatrixX::Zero(n, n);
  for (Index r = 0; r < n; ++r)
    for (Index s = pattern.outer[r]; s < pattern.outer[r + 1]; ++s)
      dense(r, pattern.inner[s]) = values[static_cast<std::size_t>(s)];
  return dense;
}

bool row_has(const solvers::petsc::CsrPattern& pattern, Index row, Index column) {
  const auto begin = pattern.inner.begin() + pattern.outer[row];
  const auto end = pattern.inner.begin() + pattern.outer[row + 1];
  return std::find(begin, end, column) != end;
}

void expect_shares_add_up(bool lower_only) {
  const solvers::petsc::NodeBlockLayout layout(2, share_dofs, share_rows);
  ASSERT_EQ(layout.holes().size(), 1U);
  const Index slot = layout.holes().front();
  const assembly::SparseMatrix frames = share_frames();
  const assembly::SparseMatrix a = stored(share_a(), lower_only);
  const assembly::SparseMatrix b = stored(share_b(), lower_only);
  const assembly::SparseMatrix whole = stored(share_a() + share_b(), lower_only);
  const auto pattern_a =
      solvers::petsc::share_pattern(a, lower_only, frames, layout, share_velocity);
  const auto pattern_b =
      solvers::petsc::share_pattern(b, lower_only, frames, layout, share_velocity);
  const auto full_a = solvers::petsc::solved_pattern(a, lower_only, frames, layout);

  // A touches nodes 0 and 3: not node 1, whose slot B alone holds.
  EXPECT_EQ(pattern_a.outer[slot + 1] - pattern_a.outer[slot], 0);
  EXPECT_TRUE(row_has(pattern_b, slot, slot));
  // Every other row is solved_pattern's.
  for (Index r = 0; r < layout.n_embedded(); ++r) {
    if (r == slot) continue;
    EXPECT_TRUE(std::equal(pattern_a.inner.begin() + pattern_a.outer[r],
                           pattern_a.inner.begin() + pattern_a.outer[r + 1],
                           full_a.inner.begin() + full_a.outer[r],
                           full_a.inner.begin() + full_a.outer[r + 1]))
        << "row " << r;
  }

  // The ranks' values add up (MatSetValuesCOO sums them) to the whole system's laid out:
  // every value is a sum of at most four products of an entry and two frame weights
  // (|q| ≤ 1), so two summation orders differ by a few ε times the largest |K_kl|.
  const MatrixX sum = laid_out(a, lower_only, frames, layout, pattern_a) +
                      laid_out(b, lower_only, frames, layout, pattern_b);
  const MatrixX expected =
      laid_out(whole, lower_only, frames, layout,
               solvers::petsc::solved_pattern(whole, lower_only, frames, layout));
  const Real bound = 16 * std::numeric_limits<Real>::epsilon() *
                     MatrixX(share_a() + share_b()).cwiseAbs().maxCoeff();
  for (Index r = 0; r < layout.n_embedded(); ++r)
    for (Index c = 0; c < layout.n_embedded(); ++c)
      if (r != slot && c != slot) {
        EXPECT_NEAR(sum(r, c), expected(r, c), bound) << r << ", " << c;
      }
  // The slot: a decoupled row with a positive diagonal, the mean |a_ii| of B's velocity
  // rows (0, 1, 2, outside the frame: 4, 5, 6).
  EXPECT_NEAR(sum(slot, slot), (4.0 + 5.0 + 6.0) / 3.0, bound);
  EXPECT_EQ(sum.row(slot).cwiseAbs().sum(), std::abs(sum(slot, slot)));
  EXPECT_EQ(sum.col(slot).cwiseAbs().sum(), std::abs(sum(slot, slot)));
}

TEST(SharePattern, SharesStoredWholeAddUpToTheLaidOutSystem) {
  expect_shares_add_up(false);
}

TEST(SharePattern, SharesStoredByTheirLowerTriangleAddUpToTheLaidOutSystem) {
  expect_shares_add_up(true);
}

} // namespace
} // namespace formflow
