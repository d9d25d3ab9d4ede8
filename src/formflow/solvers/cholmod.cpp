// SPDX-License-Identifier: MIT
// CHOLMOD supernodal Cholesky behind the LinearSolver interface.
#include "formflow/solvers/blas_thread_limit.hpp"
#include "formflow/solvers/cholmod_symbolic.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/openmp_team_limit.hpp"
#include "formflow/solvers/permuted_lower.hpp"
#include "formflow/solvers/supernodal_solve.hpp"

#include <cholmod.h>

#include <algorithm>
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
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

/// One pattern's analysis: the order, the symbolic factor and the solve's tree, as
/// CholmodSolver::analyze makes them (the permuted copy is rebuilt from the order: an
/// O(nnz) gather plan, kept out of memory).
struct Analysis {
  std::vector<Index> col_starts, rows; ///< tril(A)'s pattern, compared exactly
  std::vector<Index> order;
  std::shared_ptr<cholmod_factor> symbolic; ///< owned by the cache's cholmod_common
  FactorSize size;
  SupernodalSolve triangular;

  bool matches(const assembly::SparseMatrix& lower) const {
    const auto n = static_cast<std::size_t>(lower.cols());
    const auto nnz = static_cast<std::size_t>(lower.nonZeros());
    return col_starts.size() == n + 1 && rows.size() == nnz &&
           std::equal(col_starts.begin(), col_starts.end(), lower.outerIndexPtr()) &&
           std::equal(rows.begin(), rows.end(), lower.innerIndexPtr());
  }
};

/// The process's last few analyses, by pattern. Why: an adaptive run's end solves on
/// the mesh its last estimate settled on, and a cycle whose cheap estimate calls for
/// the full one factorises the same refined mesh's tangent again: each was a new solver
/// analysing a pattern already analysed (0.16 s at 86 514 dofs, twice a run). A pattern
/// is compared entry by entry (O(nnz), a few ms), never by a hash.
class AnalysisCache {
public:
  static AnalysisCache& instance() {
    static AnalysisCache* cache = new AnalysisCache; // never freed: used until exit
    return *cache;
  }

  /// A copy of the analysis of `lower`'s pattern, if one is kept.
  std::optional<Analysis> find(const assembly::SparseMatrix& lower) {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const Analysis& kept : kept_)
      if (kept.matches(lower)) {
        ++hits_;
        Analysis copy; // without the pattern: the caller has it
        copy.order = kept.order;
        copy.symbolic = kept.symbolic;
        copy.size = kept.size;
        copy.triangular = kept.triangular;
        return copy;
      }
    return std::nullopt;
  }

  /// Keeps `analysis` (its symbolic factor copied), dropping the oldest beyond capacity;
  /// not a pattern above largest_kept_nonzeros.
  void keep(Analysis analysis, const cholmod_factor& symbolic) {
    if (!keeps(analysis.rows.size())) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    cholmod_factor* copy = cholmod_copy_factor(const_cast<cholmod_factor*>(&symbolic), &common_);
    if (!copy) return;
    analysis.symbolic.reset(copy, [this](cholmod_factor* factor) {
      const std::lock_guard<std::mutex> guard(free_mutex_);
      cholmod_free_factor(&factor, &common_);
    });
    kept_.push_back(std::move(analysis));
    while (kept_.size() > capacity) kept_.pop_front();
  }

  std::size_t hits() const { return hits_; }

  /// Whether a pattern of `nonzeros` entries would be kept (largest_kept_nonzeros).
  static bool keeps(std::size_t nonzeros) { return nonzeros <= largest_kept_nonzeros; }

  /// The copy a solver factorises into: a new factor of the kept symbolic one.
  cholmod_factor* copy_factor(const cholmod_factor& symbolic, cholmod_common& common) {
    return cholmod_copy_factor(const_cast<cholmod_factor*>(&symbolic), &common);
  }

private:
  AnalysisCache() {
    cholmod_start(&common_);
    common_.print = 0;
  }

  /// Two: the refined mesh of the last estimate and the mesh of the run (which alternate
  /// in an adaptive run's end); more would keep meshes no later solve sees.
  static constexpr std::size_t capacity = 2;
  /// What a kept analysis costs is mostly its pattern, 4 bytes per entry of tril(A) (the
  /// symbolic factor and the tree are per supernode): up to 48 MB each. The adaptive
  /// runs' refined meshes (2D, ≤ 300 000 dofs: about 8 M entries) fit; a large 3D pattern
  /// is analysed again rather than held twice.
  static constexpr std::size_t largest_kept_nonzeros = 12'000'000;
  std::mutex mutex_, free_mutex_;
  cholmod_common common_{};
  std::deque<Analysis> kept_;
  std::atomic<std::size_t> hits_{0};
};

/// Supernodal LLᵀ of P A Pᵀ with CHOLMOD's default fill-reducing order P (AMD, METIS
/// where AMD fills much; then a weighted postorder). The permuted lower triangle is
/// formed by a gather and analysed in its natural order (solvers/cholmod_symbolic.hpp),
/// which CHOLMOD factorises as it is. Solves permute the right-hand side and the solution, and
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
    if (std::optional<Analysis> kept = AnalysisCache::instance().find(lower)) {
      factor_ = AnalysisCache::instance().copy_factor(*kept->symbolic, common_);
      if (factor_) {
        order_ = std::move(kept->order);
        permuted_ = PermutedLower(lower, order_);
        size_ = kept->size;
        triangular_ = std::move(kept->triangular);
        return true;
      }
    }
    factor_ = analyse_supernodal(lower, common_, order_, permuted_);
    if (!factor_) return false;
    // Set by cholmod_analyze: nnz(tril(A)), nnz(L), and the flops of one factorisation.
    size_ = FactorSize{common_.anz, common_.lnz, common_.fl};
    triangular_ = SupernodalSolve(*factor_);
    if (!AnalysisCache::keeps(static_cast<std::size_t>(lower.nonZeros()))) return true;
    Analysis analysis;
    analysis.col_starts.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.cols() + 1);
    analysis.rows.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros());
    analysis.order = order_;
    analysis.size = size_;
    analysis.triangular = triangular_;
    AnalysisCache::instance().keep(std::move(analysis), *factor_);
    return true;
  }
  bool factorize(const assembly::SparseMatrix& lower) override {
    if (!factor_ || !permuted_.fits(lower)) return false;
    const OpenMpTeamLimit team(cholmod_team_threads);
    const BlasThreadLimit blas(blas_threads());
    permuted_.refill(lower);
    cholmod_sparse permuted = cholmod_lower_view(permuted_.matrix());
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

std::size_t cholmod_analyses_reused() {
  return AnalysisCache::instance().hits();
}

} // namespace formflow::solvers
