// SPDX-License-Identifier: MIT
// CHOLMOD supernodal Cholesky behind the LinearSolver interface.
#include "formflow/solvers/blas_thread_limit.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/openmp_team_limit.hpp"
#include "formflow/solvers/permuted_lower.hpp"
#include "formflow/solvers/supernodal_solve.hpp"

#include <cholmod.h>

#include <vector>

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

/// A view of `matrix` as CHOLMOD's symmetric matrix stored by its lower triangle
/// (CHOLMOD reads it only; the non-const pointers are its C interface's).
cholmod_sparse lower_view(const assembly::SparseMatrix& matrix) {
  cholmod_sparse view{};
  view.nrow = static_cast<std::size_t>(matrix.rows());
  view.ncol = static_cast<std::size_t>(matrix.cols());
  view.nzmax = static_cast<std::size_t>(matrix.nonZeros());
  view.p = const_cast<Index*>(matrix.outerIndexPtr());
  view.i = const_cast<Index*>(matrix.innerIndexPtr());
  view.x = const_cast<Real*>(matrix.valuePtr());
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

/// Supernodal LLᵀ of P A Pᵀ with CHOLMOD's default fill-reducing order P (AMD, METIS
/// where AMD fills much; then a weighted postorder). The permuted lower triangle is
/// formed here (solvers/permuted_lower.hpp) and factorised in its natural order, which
/// CHOLMOD takes as it is. Solves permute the right-hand side and the solution, and
/// sweep CHOLMOD's factor on two threads (solvers/supernodal_solve.hpp).
class CholmodSolver final : public LinearSolver {
public:
  CholmodSolver() {
    cholmod_start(&common_);
    // CHOLMOD prints its own warnings (e.g. "not positive definite") unless
    // silenced; we report failures through return values instead.
    common_.print = 0;
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.final_asis = 1; // keep the supernodal factor as it is
  }
  ~CholmodSolver() override {
    cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  bool analyze(const assembly::SparseMatrix& lower) override {
    const OpenMpTeamLimit team(cholmod_team_threads);
    cholmod_free_factor(&factor_, &common_);
    size_ = {};
    factorized_ = false;
    if (!lower.isCompressed()) return false;
    // 1. The order: CHOLMOD's default strategy on A (no supernodal symbolic needed).
    cholmod_sparse view = lower_view(lower);
    common_.nmethods = 0;
    common_.postorder = 1;
    common_.supernodal = CHOLMOD_SIMPLICIAL;
    cholmod_factor* ordering = cholmod_analyze(&view, &common_);
    const bool ordered = ordering && common_.status == CHOLMOD_OK;
    if (ordered) {
      const Index* perm = static_cast<const Index*>(ordering->Perm);
      order_.assign(perm, perm + ordering->n);
      permuted_ = PermutedLower(lower, order_);
    }
    cholmod_free_factor(&ordering, &common_);
    if (!ordered) return false;
    // 2. The supernodal symbolic factor of P A Pᵀ in its natural order.
    cholmod_sparse permuted = lower_view(permuted_.matrix());
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_NATURAL;
    common_.postorder = 0;
    common_.supernodal = CHOLMOD_SUPERNODAL;
    factor_ = cholmod_analyze(&permuted, &common_);
    if (!factor_ || common_.status != CHOLMOD_OK) {
      cholmod_free_factor(&factor_, &common_);
      return false;
    }
    // Set by cholmod_analyze: nnz(tril(A)), nnz(L), and the flops of one factorisation.
    size_ = FactorSize{common_.anz, common_.lnz, common_.fl};
    triangular_ = SupernodalSolve(*factor_);
    return true;
  }
  bool factorize(const assembly::SparseMatrix& lower) override {
    if (!factor_ || !permuted_.fits(lower)) return false;
    const OpenMpTeamLimit team(cholmod_team_threads);
    const BlasThreadLimit blas(blas_threads());
    permuted_.refill(lower);
    cholmod_sparse permuted = lower_view(permuted_.matrix());
    factorized_ = cholmod_factorize(&permuted, factor_, &common_) && common_.status == CHOLMOD_OK;
    return factorized_;
  }
  bool solve(const VectorX& rhs, VectorX& solution) override {
    if (!factorized_ || rhs.size() != static_cast<Eigen::Index>(factor_->n)) return false;
    const Index n = static_cast<Index>(factor_->n);
    permuted_rhs_.resize(n);
    const Index* order = order_.data();
    for (Index k = 0; k < n; ++k) permuted_rhs_[k] = rhs[order[k]];
    triangular_.solve(*factor_, permuted_rhs_.data());
    solution.resize(n);
    for (Index k = 0; k < n; ++k) solution[order[k]] = permuted_rhs_[k];
    return true;
  }
  std::string name() const override { return "cholmod-supernodal"; }
  FactorSize factor_size() const override { return size_; }

private:
  /// One BLAS thread for a factor of small supernodes, else OpenBLAS's own count (0).
  int blas_threads() const {
    return size_.factor_flops < threaded_flops_per_nonzero * size_.factor_nonzeros ? 1 : 0;
  }

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr; ///< of P A Pᵀ, natural order
  PermutedLower permuted_;
  std::vector<Index> order_; ///< P: new row k is A's row order_[k]
  FactorSize size_;
  bool factorized_ = false;
  SupernodalSolve triangular_;     ///< the solves with factor_ (on the machine's threads)
  std::vector<Real> permuted_rhs_; ///< P b, then P x
};

} // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() {
  return std::make_unique<CholmodSolver>();
}

} // namespace formflow::solvers
