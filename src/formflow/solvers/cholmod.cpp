// SPDX-License-Identifier: MIT
// CHOLMOD supernodal Cholesky behind the LinearSolver interface.
#include "formflow/solvers/blas_thread_limit.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/openmp_team_limit.hpp"

#include <Eigen/CholmodSupport>

namespace formflow::solvers {

namespace {

/// CHOLMOD's own OpenMP teams run single-threaded (solvers/openmp_team_limit.hpp:
/// a team per supernode costs more in wake-ups than its loops save); its BLAS keeps
/// OpenBLAS's threads.
constexpr unsigned cholmod_team_threads = 1;

/// Below this many flops per factor nonzero (the mean work of a column: it grows with
/// the supernodes' size) OpenBLAS's threads do not pay in a factorisation, and it runs
/// on one (solvers/blas_thread_limit.hpp). Measured per factorisation, one thread
/// against two, 2-core AMD EPYC (docs/benchmarks.md "OpenBLAS's threads per factor"):
/// 2D Q2 at 309 122 dofs (318 flops per nonzero) 0.425 s against 0.435 s, the 3D slab
/// (232) 0.034 against 0.037 s; the 3D round rod (885) 0.455 s against 0.350 s.
constexpr double threaded_flops_per_nonzero = 500;

class CholmodSolver final : public LinearSolver {
public:
  CholmodSolver() {
    // CHOLMOD prints its own warnings (e.g. "not positive definite") unless
    // silenced; we report failures through return values instead.
    factorization_.cholmod().print = 0;
  }
  bool analyze(const assembly::SparseMatrix& lower) override {
    const OpenMpTeamLimit team(cholmod_team_threads);
    factorization_.analyzePattern(lower);
    return factorization_.info() == Eigen::Success;
  }
  bool factorize(const assembly::SparseMatrix& lower) override {
    const OpenMpTeamLimit team(cholmod_team_threads);
    const BlasThreadLimit blas(blas_threads());
    factorization_.factorize(lower);
    return factorization_.info() == Eigen::Success;
  }
  bool solve(const VectorX& rhs, VectorX& solution) override {
    const OpenMpTeamLimit team(cholmod_team_threads);
    const BlasThreadLimit blas(blas_threads());
    solution = factorization_.solve(rhs);
    return factorization_.info() == Eigen::Success;
  }
  std::string name() const override { return "cholmod-supernodal"; }
  FactorSize factor_size() const override {
    // Set by cholmod_analyze (inside analyzePattern): nnz(tril(A)), nnz(L), and
    // the flop count of one numeric factorisation. The const_cast is Eigen's: its
    // cholmod() accessor is non-const, and reading the statistics changes nothing.
    const cholmod_common& common =
        const_cast<Eigen::CholmodSupernodalLLT<assembly::SparseMatrix, Eigen::Lower>&>(
            factorization_)
            .cholmod();
    if (common.lnz <= 0) return {};
    return FactorSize{common.anz, common.lnz, common.fl};
  }

private:
  /// One BLAS thread for a factor of small supernodes, else OpenBLAS's own count (0).
  int blas_threads() const {
    const FactorSize size = factor_size();
    return size.factor_flops <
                   threaded_flops_per_nonzero * static_cast<double>(size.factor_nonzeros)
               ? 1
               : 0;
  }

  Eigen::CholmodSupernodalLLT<assembly::SparseMatrix, Eigen::Lower> factorization_;
};

} // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() {
  return std::make_unique<CholmodSolver>();
}

} // namespace formflow::solvers
