// SPDX-License-Identifier: MIT
// tril(P A Pᵀ) from A's lower triangle: the pattern, sorted rows, and refills.
#include "formflow/solvers/permuted_lower.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace formflow::solvers {
namespace {

using assembly::SparseMatrix;

/// A random symmetric pattern (a band and scattered couplings) as its lower triangle,
/// every value distinct so that a misplaced entry shows.
SparseMatrix random_lower(Index n, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_int_distribution<Index> row(0, n - 1);
  std::vector<Eigen::Triplet<Real, Index>> entries;
  for (Index j = 0; j < n; ++j) {
    entries.emplace_back(j, j, 1.0);
    if (j + 1 < n) entries.emplace_back(j + 1, j, 1.0);
    const Index other = row(generator);
    entries.emplace_back(std::max(other, j), std::min(other, j), 1.0);
  }
  SparseMatrix lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end(), [](Real a, Real) { return a; });
  lower.makeCompressed();
  for (Index e = 0; e < lower.nonZeros(); ++e) lower.valuePtr()[e] = 1.0 + e;
  return lower;
}

MatrixX symmetric_dense(const SparseMatrix& lower) {
  const MatrixX l = MatrixX(lower);
  return l + l.transpose() - MatrixX(l.diagonal().asDiagonal());
}

void expect_permuted(const SparseMatrix& lower, const std::vector<Index>& order,
                     const PermutedLower& permuted) {
  const MatrixX a = symmetric_dense(lower);
  const Index n = static_cast<Index>(order.size());
  MatrixX expected = MatrixX::Zero(n, n);
  for (Index k = 0; k < n; ++k)
    for (Index l = 0; l <= k; ++l) expected(k, l) = a(order[k], order[l]);
  EXPECT_EQ(MatrixX(permuted.matrix()), expected); // values copied, never computed
  const SparseMatrix& p = permuted.matrix();
  for (Index k = 0; k < n; ++k) {
    const Index* first = p.innerIndexPtr() + p.outerIndexPtr()[k];
    const Index* last = p.innerIndexPtr() + p.outerIndexPtr()[k + 1];
    EXPECT_TRUE(std::is_sorted(first, last)) << "column " << k;
    EXPECT_TRUE(first == last || *first >= k) << "column " << k << " is lower";
  }
}

TEST(PermutedLower, IsTheLowerTriangleOfTheSymmetricallyPermutedMatrix) {
  const Index n = 40;
  const SparseMatrix lower = random_lower(n, 3);
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  const PermutedLower permuted(lower, order);
  expect_permuted(lower, order, permuted);
}

TEST(PermutedLower, TheIdentityOrderCopiesTheMatrix) {
  const SparseMatrix lower = random_lower(25, 5);
  std::vector<Index> order(25);
  std::iota(order.begin(), order.end(), 0);
  const PermutedLower permuted(lower, order);
  EXPECT_EQ(MatrixX(permuted.matrix()), MatrixX(lower));
}

TEST(PermutedLower, RefillTakesNewValuesOnTheSamePattern) {
  const Index n = 30;
  SparseMatrix lower = random_lower(n, 9);
  std::vector<Index> order(n);
  std::iota(order.rbegin(), order.rend(), 0); // reversed: every entry changes triangle
  PermutedLower permuted(lower, order);
  for (Index e = 0; e < lower.nonZeros(); ++e) lower.valuePtr()[e] = -3.0 * e - 0.5;
  permuted.refill(lower);
  expect_permuted(lower, order, permuted);
}

TEST(PermutedLower, EntriesAboveTheDiagonalAreNotRead) {
  const Index n = 20;
  const SparseMatrix lower = random_lower(n, 13);
  MatrixX with_junk = MatrixX(lower);
  for (Index c = 1; c < n; ++c) with_junk(c - 1, c) = 123.0;
  const SparseMatrix junk = with_junk.sparseView();
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(1));
  const PermutedLower permuted(junk, order);
  expect_permuted(lower, order, permuted);
  EXPECT_TRUE(permuted.fits(junk));
  EXPECT_FALSE(permuted.fits(lower));
}

} // namespace
} // namespace formflow::solvers
