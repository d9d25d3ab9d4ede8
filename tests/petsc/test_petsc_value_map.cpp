// SPDX-License-Identifier: MIT
// solvers::petsc::ValueMap: the values PETSc's matrix gets on a known pattern are those
// of P Qᵀ K Q Pᵀ (local frames Q, the node-block layout P with its decoupled slots), for
// K stored whole or as its lower triangle, without forming the product.
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
// 6, 7 (as in test_petsc_node_block_layout.cpp).
const std::vector<Index> value_map_dofs = {0, 1, 3, 6, 7};
constexpr Index value_map_rows = 7, value_map_velocity = 5;

/// A symmetric K with a sparse pattern: a velocity band, pressure couplings, −d on the
/// pressure diagonal; entries of varied size and sign.
MatrixX value_map_matrix() {
  MatrixX k = MatrixX::Zero(value_map_rows, value_map_rows);
  for (Index i = 0; i < value_map_velocity; ++i) {
    k(i, i) = 3.0 + 1.7 * i;
    if (i + 1 < value_map_velocity) k(i, i + 1) = k(i + 1, i) = -0.9 + 0.3 * i;
  }
  k(0, 3) = k(3, 0) = 0.45;
  for (Index p = value_map_velocity; p < value_map_rows; ++p) {
    k(p, p) = -1e-3;
    k(p, p - 5) = k(p - 5, p) = 0.5 - 0.2 * p;
    k(p, p - 3) = k(p - 3, p) = 0.25;
  }
  return k;
}

/// One frame on velocity rows 3 and 4 (node 3's two free dofs), a rotation by 0.4 rad.
std::vector<assembly::LocalFrame> value_map_frames() {
  assembly::LocalFrame frame;
  frame.rows = {3, 4};
  frame.basis.resize(2, 2);
  const Real c = std::cos(0.4), s = std::sin(0.4);
  frame.basis << c, -s, s, c;
  return {frame};
}

/// The map's output on the layout's full (dense) pattern, as a dense matrix.
MatrixX mapped(const solvers::petsc::ValueMap& map, const assembly::SparseMatrix& input, Index n) {
  std::vector<Real> values(static_cast<std::size_t>(n * n));
  map.fill(input, values);
  MatrixX out(n, n);
  for (Index r = 0; r < n; ++r)
    for (Index c = 0; c < n; ++c) out(r, c) = values[static_cast<std::size_t>(r * n + c)];
  return out;
}

void expect_value_map_equals_product(bool lower_only) {
  const MatrixX k = value_map_matrix();
  const std::vector<assembly::LocalFrame> frames = value_map_frames();
  const assembly::SparseMatrix q = assembly::frame_matrix(frames, value_map_rows);
  const solvers::petsc::NodeBlockLayout layout(2, value_map_dofs, value_map_rows);
  const Index n = layout.n_embedded();
  // Expected: Qᵀ K Q moved to the layout's rows, the slot's diagonal the mean |diagonal|
  // of the framed velocity rows.
  const MatrixX framed = MatrixX(q).transpose() * k * MatrixX(q);
  MatrixX expected = MatrixX::Zero(n, n);
  for (Index i = 0; i < value_map_rows; ++i)
    for (Index j = 0; j < value_map_rows; ++j)
      expected(layout.position(i), layout.position(j)) = framed(i, j);
  const Real hole = framed.diagonal().head(value_map_velocity).cwiseAbs().mean();
  for (const Index slot : layout.holes()) expected(slot, slot) = hole;

  const MatrixX stored = lower_only ? MatrixX(k.triangularView<Eigen::Lower>()) : k;
  assembly::SparseMatrix input = stored.sparseView();
  input.makeCompressed();
  // PETSc's pattern: every entry of the layout (a superset of the product's pattern; the
  // entries outside it must come out zero).
  std::vector<Index> outer(static_cast<std::size_t>(n) + 1), inner;
  for (Index r = 0; r < n; ++r) {
    outer[static_cast<std::size_t>(r)] = r * n;
    for (Index c = 0; c < n; ++c) inner.push_back(c);
  }
  outer.back() = n * n;
  // The slot's row holds its diagonal only: drop its off-diagonal entries from the pattern.
  std::vector<Index> pruned_outer{0}, pruned_inner;
  for (Index r = 0; r < n; ++r) {
    const bool slot =
        std::find(layout.holes().begin(), layout.holes().end(), r) != layout.holes().end();
    for (Index c = 0; c < n; ++c) {
      const bool slot_column =
          std::find(layout.holes().begin(), layout.holes().end(), c) != layout.holes().end();
      if ((slot || slot_column) && r != c) continue;
      pruned_inner.push_back(c);
    }
    pruned_outer.push_back(static_cast<Index>(pruned_inner.size()));
  }
  // The solver's own pattern (solved_pattern) holds every nonzero of the product, and
  // each slot's row its diagonal alone.
  const solvers::petsc::CsrPattern solved =
      solvers::petsc::solved_pattern(input, lower_only, q, layout);
  ASSERT_EQ(solved.outer.size(), static_cast<std::size_t>(n) + 1);
  for (Index r = 0; r < n; ++r) {
    const Index* begin = solved.inner.data() + solved.outer[static_cast<std::size_t>(r)];
    const Index* end = solved.inner.data() + solved.outer[static_cast<std::size_t>(r) + 1];
    EXPECT_TRUE(std::is_sorted(begin, end));
    for (Index c = 0; c < n; ++c)
      if (expected(r, c) != 0.0) {
        EXPECT_NE(std::find(begin, end, c), end) << "entry (" << r << ", " << c << ")";
      }
  }
  for (const Index slot : layout.holes()) {
    EXPECT_EQ(solved.outer[static_cast<std::size_t>(slot) + 1] -
                  solved.outer[static_cast<std::size_t>(slot)],
              1);
  }
  const solvers::petsc::ValueMap map(input, lower_only, q, layout, pruned_outer, pruned_inner,
                                     value_map_velocity);
  std::vector<Real> values(pruned_inner.size());
  map.fill(input, values);
  // Each value is a sum of at most 4 products q_ki K_kl q_lj (a 2-dof frame on each
  // side, |q| ≤ 1): each product rounds by ≤ 2ε of itself and the sum by ≤ 3ε of
  // Σ|terms| ≤ 4 max|K|, so ≤ 20 ε max|K|. The dense expected side sums the same at most
  // 4 nonzero terms (Q has ≤ 2 per column) in another order: as much again. 64 ε covers both.
  const Real bound = 64 * std::numeric_limits<Real>::epsilon() * k.cwiseAbs().maxCoeff();
  for (Index r = 0; r < n; ++r)
    for (Index s = pruned_outer[static_cast<std::size_t>(r)];
         s < pruned_outer[static_cast<std::size_t>(r) + 1]; ++s) {
      const Index c = pruned_inner[static_cast<std::size_t>(s)];
      EXPECT_NEAR(values[static_cast<std::size_t>(s)], expected(r, c), bound)
          << "entry (" << r << ", " << c << ")";
    }
  // Every entry the pruned pattern left out is zero in the expected matrix.
  for (Index r = 0; r < n; ++r)
    for (Index c = 0; c < n; ++c) {
      const Index* begin = pruned_inner.data() + pruned_outer[static_cast<std::size_t>(r)];
      const Index* end = pruned_inner.data() + pruned_outer[static_cast<std::size_t>(r) + 1];
      if (std::find(begin, end, c) == end) {
        EXPECT_EQ(expected(r, c), 0.0);
      }
    }
}

TEST(ValueMap, GivesTheFramedLaidOutMatrixFromTheWholeMatrix) {
  expect_value_map_equals_product(false);
}

TEST(ValueMap, GivesTheFramedLaidOutMatrixFromTheLowerTriangle) {
  expect_value_map_equals_product(true);
}

TEST(ValueMap, IsTheIdentityWithoutFramesAndTellsAnotherPattern) {
  const MatrixX k = value_map_matrix();
  assembly::SparseMatrix input = k.sparseView();
  input.makeCompressed();
  const Index n = value_map_rows;
  std::vector<Index> outer{0}, inner;
  for (Index r = 0; r < n; ++r) {
    for (Index c = 0; c < n; ++c) inner.push_back(c);
    outer.push_back(static_cast<Index>(inner.size()));
  }
  const solvers::petsc::ValueMap map(input, false, assembly::SparseMatrix(),
                                     solvers::petsc::NodeBlockLayout(), outer, inner, n);
  // Without frames or layout the map is the identity on K's entries.
  EXPECT_TRUE((mapped(map, input, n).array() == k.array()).all());
  const solvers::petsc::InputPattern pattern(input);
  EXPECT_TRUE(pattern.matches(input));
  MatrixX other = k;
  other(1, 4) = other(4, 1) = 1.0; // one more entry: another pattern
  assembly::SparseMatrix changed = other.sparseView();
  changed.makeCompressed();
  EXPECT_FALSE(pattern.matches(changed));
}

} // namespace
} // namespace formflow
