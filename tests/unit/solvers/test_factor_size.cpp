// SPDX-License-Identifier: MIT
// The factor sizes the direct back-ends report (summary.json linear_algebra
// matrix_nonzeros / factor_nonzeros / factor_flops), on matrices whose Cholesky
// factor's pattern is known exactly.
#include "formflow/solvers/linear_solver.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace formflow {
namespace {

using assembly::SparseMatrix;

SparseMatrix from_triplets(Index n, const std::vector<Eigen::Triplet<Real, Index>>& entries) {
  SparseMatrix matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  return matrix;
}

/// Lower triangle of the tridiagonal SPD matrix tridiag(−1, 4, −1) of size n.
SparseMatrix tridiagonal_lower(Index n) {
  std::vector<Eigen::Triplet<Real, Index>> entries;
  for (Index i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 4.0);
    if (i + 1 < n) entries.emplace_back(i + 1, i, -1.0);
  }
  return from_triplets(n, entries);
}

TEST(FactorSize, CholmodCountsATridiagonalFactorWithoutFill) {
  // The graph is a path: minimum degree (AMD, which CHOLMOD tries first and
  // keeps unless another ordering has less fill) eliminates an end vertex
  // (degree 1) at each step, which creates no fill, so nnz(L) = nnz(tril A).
  const Index n = 50;
  const auto solver = solvers::make_cholmod_solver();
  EXPECT_EQ(solver->factor_size().factor_nonzeros, -1) << "nothing analysed yet";
  ASSERT_TRUE(solver->analyze(tridiagonal_lower(n)));
  ASSERT_TRUE(solver->factorize(tridiagonal_lower(n)));
  const solvers::FactorSize size = solver->factor_size();
  EXPECT_EQ(size.matrix_nonzeros, 2 * n - 1);
  EXPECT_EQ(size.factor_nonzeros, 2 * n - 1);
  EXPECT_GT(size.factor_flops, 0);
}

TEST(FactorSize, CholmodCountsADenseFactor) {
  // A dense SPD matrix: L is its full lower triangle whatever the ordering.
  const Index n = 12;
  std::vector<Eigen::Triplet<Real, Index>> entries;
  for (Index j = 0; j < n; ++j)
    for (Index i = j; i < n; ++i) entries.emplace_back(i, j, i == j ? 2.0 * n : 1.0);
  const SparseMatrix lower = from_triplets(n, entries);
  const auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(lower));
  const solvers::FactorSize size = solver->factor_size();
  EXPECT_EQ(size.matrix_nonzeros, n * (n + 1) / 2);
  EXPECT_EQ(size.factor_nonzeros, n * (n + 1) / 2);
  // CHOLMOD counts Σ_k c_k² flops for column counts c_k = n, n − 1, …, 1: n(n+1)(2n+1)/6 ≥ n³/3.
  EXPECT_GE(size.factor_flops, n * n * n / 3.0);
}

TEST(FactorSize, UmfpackReportsItsMatrixOnly) {
  const Index n = 20;
  SparseMatrix full = tridiagonal_lower(n);
  full = SparseMatrix(full.selfadjointView<Eigen::Lower>());
  const auto solver = solvers::make_umfpack_solver();
  ASSERT_TRUE(solver->analyze(full));
  const solvers::FactorSize size = solver->factor_size();
  EXPECT_EQ(size.matrix_nonzeros, 3 * n - 2);
  EXPECT_EQ(size.factor_nonzeros, -1) << "not reported: Eigen keeps UMFPACK's counts private";
}

} // namespace
} // namespace formflow
