// SPDX-License-Identifier: MIT
// solvers::petsc::NodeBlockLayout: the velocity block laid out node by node (a constant
// block size for AMG's nodal options) is a renumbering plus decoupled rows, so the laid
// out system has the same solution on the free dofs.
#include "formflow/solvers/petsc/node_block_layout.hpp"
#include "formflow/solvers/petsc/value_map.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <limits>
#include <vector>

namespace formflow {
namespace {

// 2D (two components), four mesh nodes: node 0 free, node 1 with its x prescribed (a
// symmetry line), node 2 prescribed whole (the ram), node 3 free; two pressure rows.
// Velocity rows 0..4 are the mesh dofs 0, 1, 3, 6, 7.
const std::vector<Index> node_layout_dofs = {0, 1, 3, 6, 7};
constexpr Index node_layout_rows = 7;

TEST(NodeBlockLayout, GivesEveryNodeWithAFreeDofAFullBlock) {
  const solvers::petsc::NodeBlockLayout layout(2, node_layout_dofs, node_layout_rows);
  EXPECT_EQ(layout.n_velocity_embedded(), 6); // nodes 0, 1, 3; node 2 has no free dof
  EXPECT_EQ(layout.n_embedded(), 8);          // and the two pressure rows after them
  VectorX x(node_layout_rows);
  x << 1, 2, 3, 4, 5, 6, 7;
  const VectorX y = layout.embed(x);
  VectorX expected(8);
  expected << 1, 2, 0, 3, 4, 5, 6, 7; // node 1's x slot is the hole
  EXPECT_EQ(y, expected);
  EXPECT_EQ(layout.restrict(std::span<const Real>(y.data(), 8)), x);
}

TEST(NodeBlockLayout, TheLaidOutSystemHasTheSameSolution) {
  const solvers::petsc::NodeBlockLayout layout(2, node_layout_dofs, node_layout_rows);
  // An indefinite saddle-point-like system: SPD velocity block, coupling, −I pressure.
  MatrixX dense = MatrixX::Zero(node_layout_rows, node_layout_rows);
  for (Index i = 0; i < 5; ++i) {
    dense(i, i) = 4 + i;
    if (i + 1 < 5) dense(i, i + 1) = dense(i + 1, i) = -1;
  }
  for (Index k = 5; k < 7; ++k) {
    dense(k, k) = -1;
    dense(k, k - 5) = dense(k - 5, k) = 0.5;
    dense(k, k - 3) = dense(k - 3, k) = 0.25;
  }
  assembly::SparseMatrix matrix = dense.sparseView();
  matrix.makeCompressed();
  VectorX rhs(node_layout_rows);
  rhs << 1, -2, 3, 0.5, -1, 2, 1;
  // The laid-out matrix as PETSc gets it: the pattern and the values of the solver's
  // ValueMap (no frames).
  const solvers::petsc::CsrPattern pattern =
      solvers::petsc::solved_pattern(matrix, false, assembly::SparseMatrix(), layout);
  const solvers::petsc::ValueMap map(matrix, false, assembly::SparseMatrix(), layout, pattern.outer,
                                     pattern.inner, 5);
  std::vector<Real> values(pattern.inner.size());
  map.fill(matrix, values);
  MatrixX embedded = MatrixX::Zero(8, 8);
  for (Index r = 0; r < 8; ++r)
    for (Index s = pattern.outer[r]; s < pattern.outer[r + 1]; ++s)
      embedded(r, pattern.inner[s]) = values[static_cast<std::size_t>(s)];
  const Real hole = (4 + 5 + 6 + 7 + 8) / 5.0; // the mean |diagonal| of the velocity rows
  EXPECT_DOUBLE_EQ(embedded(2, 2), hole);
  // The hole's row and column hold only its diagonal entry.
  EXPECT_EQ(embedded.row(2).cwiseAbs().sum(), hole);
  EXPECT_EQ(embedded.col(2).cwiseAbs().sum(), hole);
  const VectorX direct = dense.fullPivLu().solve(rhs);
  const VectorX solved = embedded.fullPivLu().solve(layout.embed(rhs));
  const VectorX laid_out = layout.restrict(std::span<const Real>(solved.data(), 8));
  // Both are backward-stable solves of systems with the same nonzero singular values
  // plus the hole's: each errs by at most a small multiple of κ ε relative, κ the larger
  // condition number of the two.
  const Eigen::JacobiSVD<MatrixX> svd(embedded);
  const Real kappa = svd.singularValues()(0) / svd.singularValues().tail(1)(0);
  const Real tolerance = 10 * kappa * std::numeric_limits<Real>::epsilon();
  EXPECT_LE((laid_out - direct).norm(), tolerance * direct.norm());
}

} // namespace
} // namespace formflow
