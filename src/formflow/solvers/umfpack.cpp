// SPDX-License-Identifier: MIT
// UMFPACK sparse LU behind the LinearSolver interface, for the indefinite
// saddle-point systems of the continuous-pressure mixed problem.
#include "formflow/solvers/linear_solver.hpp"

#include <Eigen/UmfPackSupport>

namespace formflow::solvers {

namespace {

/// Why LU and not CHOLMOD's LDLᵀ: with d = 0 the pressure block is zero, so a
/// symmetric factorisation without pivoting meets zero pivots; UMFPACK pivots
/// (threshold partial pivoting, preferring the diagonal for this symmetric
/// pattern) and serves d > 0 and d = 0 alike. Analysis (ordering, symbolic
/// factorisation) once; numeric factorisation per secant step.
class UmfpackSolver final : public LinearSolver {
 public:
  bool analyze(const assembly::SparseMatrix& full) override {
    factorization_.analyzePattern(full);
    return factorization_.info() == Eigen::Success;
  }
  bool factorize(const assembly::SparseMatrix& full) override {
    factorization_.factorize(full);
    return factorization_.info() == Eigen::Success;
  }
  bool solve(const VectorX& rhs, VectorX& solution) override {
    solution = factorization_.solve(rhs);
    return factorization_.info() == Eigen::Success;
  }
  std::string name() const override { return "umfpack-lu"; }

 private:
  Eigen::UmfPackLU<assembly::SparseMatrix> factorization_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

}  // namespace formflow::solvers
