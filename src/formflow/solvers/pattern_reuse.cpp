// SPDX-License-Identifier: MIT
// reuse_analysis: analyse a pattern once, however many loops factorise on it.
#include "formflow/solvers/pattern_reuse.hpp"

#include <algorithm>
#include <utility>

namespace formflow::solvers {

namespace {

class PatternReuse final : public LinearSolver {
public:
  explicit PatternReuse(std::unique_ptr<LinearSolver> solver) : solver_(std::move(solver)) {}

  bool analyze(const assembly::SparseMatrix& matrix) override {
    if (analysed_ && same_pattern(matrix)) return true;
    analysed_ = solver_->analyze(matrix);
    if (analysed_) remember(matrix);
    return analysed_;
  }
  bool factorize(const assembly::SparseMatrix& matrix) override {
    return solver_->factorize(matrix);
  }
  bool solve(const VectorX& rhs, VectorX& solution) override {
    return solver_->solve(rhs, solution);
  }
  bool solve_whole(const VectorX& rhs, VectorX& solution) override {
    return solver_->solve_whole(rhs, solution);
  }
  bool finite(const VectorX& solution) const override { return solver_->finite(solution); }
  std::string name() const override { return solver_->name(); }
  long krylov_iterations() const override { return solver_->krylov_iterations(); }
  FactorSize factor_size() const override { return solver_->factor_size(); }
  void set_fields(Index n_first, std::vector<VectorX> near_null_space) override {
    solver_->set_fields(n_first, std::move(near_null_space));
  }
  void set_velocity_nodes(int components, std::vector<Index> dof_of_velocity) override {
    solver_->set_velocity_nodes(components, std::move(dof_of_velocity));
  }
  bool take_saddle_point_blocks(const assembly::SparseMatrix& coupling,
                                const assembly::SparseMatrix& pressure_block) override {
    return solver_->take_saddle_point_blocks(coupling, pressure_block);
  }
  // The rest of the interface goes through too: a wrapped iterative back-end keeps its
  // Schur preconditioner, frames, guesses, inexact tolerances and options prefix.
  void set_schur_preconditioner(const assembly::SparseMatrix& matrix, Index cell_block) override {
    solver_->set_schur_preconditioner(matrix, cell_block);
  }
  void set_local_frames(std::vector<assembly::LocalFrame> frames) override {
    solver_->set_local_frames(std::move(frames));
  }
  void set_initial_guess(VectorX guess) override { solver_->set_initial_guess(std::move(guess)); }
  bool set_solve_tolerance(Real reduction) override {
    return solver_->set_solve_tolerance(reduction);
  }
  void set_options_prefix(const std::string& prefix) override {
    solver_->set_options_prefix(prefix);
  }

private:
  bool same_pattern(const assembly::SparseMatrix& matrix) const {
    if (matrix.rows() != rows_ || matrix.cols() != static_cast<Index>(starts_.size()) - 1 ||
        !matrix.isCompressed())
      return false;
    const Index nnz = matrix.nonZeros();
    return nnz == static_cast<Index>(indices_.size()) &&
           std::equal(starts_.begin(), starts_.end(), matrix.outerIndexPtr()) &&
           std::equal(indices_.begin(), indices_.end(), matrix.innerIndexPtr());
  }
  void remember(const assembly::SparseMatrix& matrix) {
    rows_ = matrix.rows();
    if (!matrix.isCompressed()) { // never reused: same_pattern refuses it
      starts_.clear();
      indices_.clear();
      return;
    }
    starts_.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + matrix.cols() + 1);
    indices_.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros());
  }

  std::unique_ptr<LinearSolver> solver_;
  bool analysed_ = false;
  Index rows_ = 0;
  std::vector<assembly::SparseMatrix::StorageIndex> starts_, indices_;
};

} // namespace

std::unique_ptr<LinearSolver> reuse_analysis(std::unique_ptr<LinearSolver> solver) {
  return std::make_unique<PatternReuse>(std::move(solver));
}

} // namespace formflow::solvers
