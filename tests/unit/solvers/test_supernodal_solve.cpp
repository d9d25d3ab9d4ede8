// SPDX-License-Identifier: MIT
// The supernodal triangular solves on two bins of the elimination tree: the solution of
// L Lᵀ x = b, and the same bits on one thread and on two.
#include "formflow/solvers/supernodal_solve.hpp"

#include "formflow/solvers/cholmod_symbolic.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/permuted_lower.hpp"
#include "support/random_vector.hpp"
#include "support/thread_cap.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <limits>
#include <thread>
#include <vector>

namespace formflow::solvers {
namespace {

using assembly::SparseMatrix;
using testing::random_vector;
using testing::ThreadCap;

/// The 9-point stencil on an m × m grid (a Q1-like coupling; SPD, diagonally dominant),
/// lower triangle: a 2D factor large enough that the solve runs on two threads.
SparseMatrix grid_matrix(int m) {
  std::vector<Eigen::Triplet<Real, Index>> lower;
  const auto at = [m](int i, int j) { return static_cast<Index>(j * m + i); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      lower.emplace_back(at(i, j), at(i, j), 9.0 + 1e-3 * ((i * 7 + j * 3) % 11));
      for (int dj = 0; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          if (dj == 0 && di <= 0) continue;
          const int ni = i + di, nj = j + dj;
          if (ni < 0 || ni >= m || nj >= m) continue;
          lower.emplace_back(at(ni, nj), at(i, j), -1.0);
        }
    }
  SparseMatrix matrix(m * m, m * m);
  matrix.setFromTriplets(lower.begin(), lower.end());
  matrix.makeCompressed();
  return matrix;
}

VectorX solved(const SparseMatrix& lower, const VectorX& rhs, const char* threads) {
  const ThreadCap cap(threads);
  auto solver = make_cholmod_solver();
  EXPECT_TRUE(solver->analyze(lower) && solver->factorize(lower));
  VectorX x;
  EXPECT_TRUE(solver->solve(rhs, x));
  return x;
}

/// The symbolic supernodal factor of `lower` as the CHOLMOD solver makes it
/// (solvers/cholmod_symbolic.hpp), owned.
class SymbolicFactor {
public:
  explicit SymbolicFactor(const SparseMatrix& lower) {
    cholmod_start(&common_);
    factor_ = analyse_supernodal(lower, common_, order_, permuted_);
    EXPECT_NE(factor_, nullptr);
  }
  ~SymbolicFactor() {
    cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  SymbolicFactor(const SymbolicFactor&) = delete;
  SymbolicFactor& operator=(const SymbolicFactor&) = delete;
  const cholmod_factor& factor() const { return *factor_; }
  /// The most nonzeros in a column of L: the most rows of a supernode.
  Index largest_column() const {
    const Index* pi = static_cast<const Index*>(factor_->pi);
    Index most = 0;
    for (std::size_t s = 0; s < factor_->nsuper; ++s) most = std::max(most, pi[s + 1] - pi[s]);
    return most;
  }

private:
  cholmod_common common_{};
  std::vector<Index> order_;
  PermutedLower permuted_;
  cholmod_factor* factor_ = nullptr;
};

TEST(SupernodalSolve, SolvesTheSystemToItsBackwardErrorBound) {
  // Cholesky's backward error (Higham, Accuracy and Stability, Thm 10.4 with 10.5):
  // (A + ΔA) x̂ = b with |ΔA| ≤ γ_{3m+1} |L||Lᵀ|, m the most nonzeros of a column of L,
  // γ_k = kε/(1 − kε). By Cauchy–Schwarz (|L||Lᵀ|)_ij ≤ √(a_ii a_jj) ≤ max a_ii, and a
  // row of |L||Lᵀ| has at most 2m nonzeros, so ‖b − A x̂‖∞ ≤ γ_{3m+1} 2m max a_ii ‖x̂‖∞:
  // a bound from the factor's shape, about 1e-9 ‖x̂‖∞ here, where a wrong sweep leaves
  // residuals of the order of ‖b‖.
  const SparseMatrix lower = grid_matrix(150);
  const VectorX rhs = random_vector(lower.rows(), 4);
  const VectorX x = solved(lower, rhs, "2");
  const VectorX residual = SparseMatrix(lower.selfadjointView<Eigen::Lower>()) * x - rhs;
  const double m = SymbolicFactor(lower).largest_column();
  const double k = 3 * m + 1, eps = std::numeric_limits<double>::epsilon();
  const double gamma = k * eps / (1 - k * eps);
  const double bound = gamma * 2 * m * lower.diagonal().maxCoeff() * x.lpNorm<Eigen::Infinity>();
  EXPECT_LE(residual.lpNorm<Eigen::Infinity>(), bound);
  EXPECT_GT(x.lpNorm<Eigen::Infinity>(), 0.0);
}

TEST(SupernodalSolve, OneThreadAndTwoGiveTheSameBits) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one hardware thread";
  const SparseMatrix lower = grid_matrix(150); // 22 500 rows: above the threads' size
  const VectorX rhs = random_vector(lower.rows(), 8);
  EXPECT_EQ(solved(lower, rhs, "1"), solved(lower, rhs, "2"));
}

TEST(SupernodalSolve, MostOfATwoDimensionalTreeIsInTheBins) {
  // The grid in CHOLMOD's fill-reducing order, as the solver factorises it: the subtrees
  // below the top carry most of the solve's work (what runs on two threads).
  const SymbolicFactor symbolic(grid_matrix(100));
  const SupernodalSolve schedule(symbolic.factor());
  EXPECT_GT(schedule.parallel_share(), 0.75);
}

} // namespace
} // namespace formflow::solvers
