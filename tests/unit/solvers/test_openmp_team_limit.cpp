// SPDX-License-Identifier: MIT
// CHOLMOD's OpenMP teams are capped (solvers/openmp_team_limit.hpp): a factorisation opens
// no threads of its own. Without the cap, CHOLMOD 3 opens a team of four (its compiled
// size) in its supernodal loops, whatever OMP_NUM_THREADS says, and libgomp keeps those
// threads for the life of the process.
#include "formflow/core/parallel_tasks.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "support/grid_laplacian.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

namespace formflow::testing {
namespace {

/// The threads of this process (/proc/self/task).
int threads_of_this_process() {
  int count = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++count;
  return count;
}

// Its own suite, so ctest runs it in a process of its own: no earlier test can have
// started libgomp's pool already.
TEST(CholmodOpenMpTeams, FactorisationStartsNoThreads) {
  // n = 10 000 rows, far above the sizes at which CHOLMOD's loops open a team (it clears
  // its n-long map in parallel once n > 128), with supernodes of hundreds of columns.
  const assembly::SparseMatrix matrix = grid_laplacian_lower(100);
  // formflow's own helpers (the solve's sweep runs on them) live for the process: started
  // first, they are in the count before and after.
  start_task_helpers();
  const int before = threads_of_this_process();
  auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(matrix));
  ASSERT_TRUE(solver->factorize(matrix));
  VectorX solution;
  ASSERT_TRUE(solver->solve(VectorX::Ones(matrix.rows()), solution));
  EXPECT_EQ(threads_of_this_process(), before)
      << "CHOLMOD opened an OpenMP team (solvers/openmp_team_limit.hpp)";
  // And the solve is a solve: Cholesky's backward error is bounded by γ_w |L||Lᵀ| with w
  // the length of the inner products, here the band width m + 1 = 101 of the nested
  // dissection's separators at most, so |r| ≤ 4 (m + 1) ε ‖A‖∞ ‖x‖ with ‖A‖∞ = 8 (the
  // factor 4: ‖|L||Lᵀ|‖ ≤ ‖A‖ for an SPD M-matrix, twice for the forward and back sweeps).
  const VectorX residual =
      matrix.selfadjointView<Eigen::Lower>() * solution - VectorX::Ones(matrix.rows());
  const Real bound = 4.0 * 101.0 * std::numeric_limits<Real>::epsilon() * 8.0 * solution.norm();
  EXPECT_LT(residual.norm(), bound);
}

} // namespace
} // namespace formflow::testing
