// SPDX-License-Identifier: MIT
// The supernodal triangular solves on two bins of the elimination tree: the solution of
// L Lᵀ x = b, and the same bits on one thread and on two.
#include "formflow/solvers/supernodal_solve.hpp"

#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/permuted_lower.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace formflow::solvers {
namespace {

using assembly::SparseMatrix;

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

VectorX random_vector(Index n, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX v(n);
  for (Index k = 0; k < n; ++k) v[k] = uniform(generator);
  return v;
}

/// Sets OMP_NUM_THREADS (compute_threads()'s cap) while alive.
class ThreadCap {
public:
  explicit ThreadCap(const char* value) {
    if (const char* old = std::getenv("OMP_NUM_THREADS")) old_ = old, had_ = true;
    setenv("OMP_NUM_THREADS", value, 1);
  }
  ~ThreadCap() {
    if (had_)
      setenv("OMP_NUM_THREADS", old_.c_str(), 1);
    else
      unsetenv("OMP_NUM_THREADS");
  }
  ThreadCap(const ThreadCap&) = delete;
  ThreadCap& operator=(const ThreadCap&) = delete;

private:
  std::string old_;
  bool had_ = false;
};

VectorX solved(const SparseMatrix& lower, const VectorX& rhs, const char* threads) {
  const ThreadCap cap(threads);
  auto solver = make_cholmod_solver();
  EXPECT_TRUE(solver->analyze(lower) && solver->factorize(lower));
  VectorX x;
  EXPECT_TRUE(solver->solve(rhs, x));
  return x;
}

TEST(SupernodalSolve, SolvesTheSystemToItsConditionsAccuracy) {
  // κ ≤ (9 + 8)/(9 − 8) = 17 (Gershgorin): a backward-stable solve leaves a residual of
  // a few ε·κ·‖A‖‖x‖; 1e-12 of ‖b‖ is far above that and far below any wrong sweep.
  const SparseMatrix lower = grid_matrix(150);
  const VectorX rhs = random_vector(lower.rows(), 4);
  const VectorX x = solved(lower, rhs, "2");
  const VectorX residual = SparseMatrix(lower.selfadjointView<Eigen::Lower>()) * x - rhs;
  EXPECT_LT(residual.norm(), 1e-12 * rhs.norm());
}

TEST(SupernodalSolve, OneThreadAndTwoGiveTheSameBits) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one hardware thread";
  const SparseMatrix lower = grid_matrix(150); // 22 500 rows: above the threads' size
  const VectorX rhs = random_vector(lower.rows(), 8);
  EXPECT_EQ(solved(lower, rhs, "1"), solved(lower, rhs, "2"));
}

cholmod_sparse lower_view(const SparseMatrix& lower) {
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<std::size_t>(lower.rows());
  view.nzmax = static_cast<std::size_t>(lower.nonZeros());
  view.p = const_cast<Index*>(lower.outerIndexPtr());
  view.i = const_cast<Index*>(lower.innerIndexPtr());
  view.x = const_cast<Real*>(lower.valuePtr());
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = view.packed = 1;
  return view;
}

TEST(SupernodalSolve, MostOfATwoDimensionalTreeIsInTheBins) {
  // The grid in CHOLMOD's fill-reducing order, as the solver factorises it: the subtrees
  // below the top carry most of the solve's work (what runs on two threads).
  const SparseMatrix lower = grid_matrix(100);
  cholmod_common common;
  cholmod_start(&common);
  cholmod_sparse view = lower_view(lower);
  cholmod_factor* ordering = cholmod_analyze(&view, &common);
  ASSERT_NE(ordering, nullptr);
  const Index* perm = static_cast<const Index*>(ordering->Perm);
  const std::vector<Index> order(perm, perm + ordering->n);
  cholmod_free_factor(&ordering, &common);
  const PermutedLower permuted(lower, order);
  cholmod_sparse permuted_view = lower_view(permuted.matrix());
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_NATURAL;
  common.postorder = 0;
  common.supernodal = CHOLMOD_SUPERNODAL;
  cholmod_factor* factor = cholmod_analyze(&permuted_view, &common);
  ASSERT_NE(factor, nullptr);
  const SupernodalSolve schedule(*factor);
  EXPECT_GT(schedule.parallel_share(), 0.75);
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
}

} // namespace
} // namespace formflow::solvers
