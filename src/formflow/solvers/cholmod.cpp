// SPDX-License-Identifier: MIT
// CHOLMOD supernodal Cholesky behind the LinearSolver interface.
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/openmp_team_limit.hpp"

#include <Eigen/CholmodSupport>

namespace formflow::solvers {

namespace {

/// CHOLMOD's own OpenMP teams run single-threaded (solvers/openmp_team_limit.hpp:
/// a team per supernode costs more in wake-ups than its loops save); its BLAS keeps
/// OpenBLAS's threads.
constexpr unsigned cholmod_team_threads = 1;

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
    factorization_.factorize(lower);
    return factorization_.info() == Eigen::Success;
  }
  bool solve(const VectorX& rhs, VectorX& solution) override {
    const OpenMpTeamLimit team(cholmod_team_threads);
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
  Eigen::CholmodSupernodalLLT<assembly::SparseMatrix, Eigen::Lower> factorization_;
};

} // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() {
  return std::make_unique<CholmodSolver>();
}

} // namespace formflow::solvers
