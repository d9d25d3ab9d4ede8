// SPDX-License-Identifier: MIT
// The direct solvers by name (solver.linear), and UMFPACK for symmetric systems
// stored as their lower triangle.
#include "formflow/core/error.hpp"
#include "formflow/solvers/linear_solver.hpp"
#if FORMFLOW_WITH_PETSC
#include "formflow/solvers/petsc/petsc_solver.hpp"
#endif

namespace formflow::solvers {

namespace {

/// UMFPACK on a symmetric matrix given by its lower triangle (the velocity systems,
/// assembled for CHOLMOD): LU needs both triangles, so each call expands L to
/// L + Lᵀ − diag(L) first, one sparse transpose-add per factorisation.
class FullFromLower final : public LinearSolver {
public:
  explicit FullFromLower(std::unique_ptr<LinearSolver> full) : full_(std::move(full)) {}
  bool analyze(const assembly::SparseMatrix& lower) override {
    return full_->analyze(expand(lower));
  }
  bool factorize(const assembly::SparseMatrix& lower) override {
    return full_->factorize(expand(lower));
  }
  bool solve(const VectorX& rhs, VectorX& solution) override { return full_->solve(rhs, solution); }
  std::string name() const override { return full_->name(); }

private:
  const assembly::SparseMatrix& expand(const assembly::SparseMatrix& lower) {
    const assembly::SparseMatrix strict = lower.triangularView<Eigen::StrictlyLower>();
    expanded_ = lower;
    expanded_ += assembly::SparseMatrix(strict.transpose());
    return expanded_;
  }
  std::unique_ptr<LinearSolver> full_;
  assembly::SparseMatrix expanded_;
};

} // namespace

std::string_view linear_solver_name(LinearSolverKind kind) {
  switch (kind) {
  case LinearSolverKind::Cholmod: return "cholmod";
  case LinearSolverKind::Umfpack: return "umfpack";
  case LinearSolverKind::Petsc: return "petsc";
  }
  return "unknown";
}

bool can_serve(LinearSolverKind kind, MatrixStorage storage) {
  // CHOLMOD's LLᵀ needs a positive definite matrix; UMFPACK's LU takes any, and so
  // does PETSc (MUMPS LU by default for the full saddle point).
  return kind != LinearSolverKind::Cholmod || storage == MatrixStorage::SymmetricLower;
}

bool is_built(LinearSolverKind kind) {
#if FORMFLOW_WITH_PETSC
  static_cast<void>(kind);
  return true;
#else
  return kind != LinearSolverKind::Petsc;
#endif
}

std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind, MatrixStorage storage,
                                                 const std::string& petsc_options) {
  FF_ASSERT(can_serve(kind, storage), "the case validation refuses a solver that cannot serve");
  FF_ASSERT(is_built(kind), "the case validation refuses a back-end this build lacks");
  switch (kind) {
  case LinearSolverKind::Cholmod: return make_cholmod_solver();
  case LinearSolverKind::Umfpack:
    if (storage == MatrixStorage::Full) return make_umfpack_solver();
    return std::make_unique<FullFromLower>(make_umfpack_solver());
  case LinearSolverKind::Petsc:
#if FORMFLOW_WITH_PETSC
    return make_petsc_solver(storage, petsc_options);
#else
    static_cast<void>(petsc_options);
    break;
#endif
  }
  return make_cholmod_solver();
}

} // namespace formflow::solvers
