// SPDX-License-Identifier: MIT
// GMRES on J = T + N, matrix free, preconditioned by the Cholesky factor of T.
#include "formflow/solvers/coupled_tangent_solve.hpp"

#include <Eigen/SparseCore>
#include <unsupported/Eigen/IterativeSolvers>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace formflow::solvers {
namespace {
class JacobianOperator;
} // namespace
} // namespace formflow::solvers

// Eigen's matrix-free pattern ("Matrix-free solvers" in the Eigen manual): an
// EigenBase type with the traits of a sparse matrix and its own product.
namespace Eigen::internal {
template <>
struct traits<formflow::solvers::JacobianOperator>
    : public traits<Eigen::SparseMatrix<formflow::Real, Eigen::ColMajor, formflow::Index>> {};
} // namespace Eigen::internal

namespace formflow::solvers {
namespace {

/// J x = T x + N x with T from its lower triangle.
class JacobianOperator : public Eigen::EigenBase<JacobianOperator> {
public:
  using Scalar = Real;
  using RealScalar = Real;
  using StorageIndex = Index;
  enum {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = false
  };

  JacobianOperator(const assembly::SparseMatrix& lower, const CouplingProduct& coupling,
                   const ShareSum& add_up_shares)
      : lower_(lower), coupling_(coupling), add_up_shares_(add_up_shares) {}
  Eigen::Index rows() const { return lower_.rows(); }
  Eigen::Index cols() const { return lower_.cols(); }

  template <typename Rhs>
  Eigen::Product<JacobianOperator, Rhs, Eigen::AliasFreeProduct>
  operator*(const Eigen::MatrixBase<Rhs>& x) const {
    return Eigen::Product<JacobianOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

  void apply(const VectorX& x, VectorX& y) const {
    y.noalias() = lower_.selfadjointView<Eigen::Lower>() * x;
    coupling_(x, y);
    if (add_up_shares_) add_up_shares_(y); // a distributed run's shares of J x
  }

private:
  const assembly::SparseMatrix& lower_;
  const CouplingProduct& coupling_;
  const ShareSum& add_up_shares_;
};

/// T⁻¹ from the factorisation held by a LinearSolver (already computed).
class FactorPreconditioner {
public:
  void attach(LinearSolver* factorized) { factorized_ = factorized; }
  template <typename Matrix> FactorPreconditioner& analyzePattern(const Matrix&) { return *this; }
  template <typename Matrix> FactorPreconditioner& factorize(const Matrix&) { return *this; }
  template <typename Matrix> FactorPreconditioner& compute(const Matrix&) { return *this; }
  template <typename Rhs> VectorX solve(const Rhs& b) const {
    VectorX x;
    if (!factorized_->solve_whole(VectorX(b), x))
      x.setConstant(b.size(), std::numeric_limits<Real>::quiet_NaN());
    return x;
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
  LinearSolver* factorized_ = nullptr;
};

} // namespace
} // namespace formflow::solvers

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<formflow::solvers::JacobianOperator, Rhs, SparseShape, DenseShape,
                            GemvProduct>
    : generic_product_impl_base<formflow::solvers::JacobianOperator, Rhs,
                                generic_product_impl<formflow::solvers::JacobianOperator, Rhs>> {
  using Scalar = typename Product<formflow::solvers::JacobianOperator, Rhs>::Scalar;
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const formflow::solvers::JacobianOperator& lhs,
                            const Rhs& rhs, const Scalar& alpha) {
    formflow::VectorX product;
    lhs.apply(formflow::VectorX(rhs), product);
    dst += alpha * product;
  }
};
} // namespace Eigen::internal

namespace formflow::solvers {
namespace {

/// Left-preconditioned GMRES(krylov_basis) on ghosted vectors: every inner product
/// through `dot`, every other operation entry by entry (a rank's NaN entries, the ones
/// it does not hold, stay its own). Stops as Eigen's does: when |g_k|/‖M⁻¹b‖ (the
/// preconditioned residual's norm relative to the first one's) is below `tolerance`, or
/// after `max_iterations` in all.
KrylovOutcome ghosted_gmres(const std::function<void(const VectorX&, VectorX&)>& apply,
                            const std::function<bool(const VectorX&, VectorX&)>& precondition,
                            const GhostedDot& dot, const VectorX& rhs, VectorX& x, Real tolerance,
                            int max_iterations);

} // namespace

/// Eigen's GMRES keeps its Householder basis in a dense n × (restart + 1) matrix,
/// allocated and zeroed on every call (52 MB at 309 k dofs for restart 20). Newton
/// steps take 1–4 iterations, so a basis of 8 (one restart in the rare longer solve)
/// keeps that cost small without changing any measured step.
constexpr int krylov_basis = 8;

KrylovOutcome solve_coupled_tangent(const assembly::SparseMatrix& tangent_lower,
                                    const CouplingProduct& coupling, LinearSolver& factorized,
                                    const VectorX& rhs, VectorX& delta, Real tolerance,
                                    int max_iterations, const ShareSum& add_up_shares,
                                    const GhostedDot& dot) {
  KrylovOutcome outcome;
  const JacobianOperator jacobian(tangent_lower, coupling, add_up_shares);
  if (dot) {
    const auto apply = [&](const VectorX& x, VectorX& y) { jacobian.apply(x, y); };
    const auto precondition = [&](const VectorX& b, VectorX& x) {
      return factorized.solve_whole(b, x) && factorized.finite(x);
    };
    return ghosted_gmres(apply, precondition, dot, rhs, delta, tolerance, max_iterations);
  }
  Eigen::GMRES<JacobianOperator, FactorPreconditioner> gmres;
  gmres.preconditioner().attach(&factorized);
  gmres.setTolerance(tolerance);
  gmres.setMaxIterations(max_iterations);
  gmres.set_restart(std::min(max_iterations, krylov_basis));
  gmres.compute(jacobian);
  // From δ = 0, so that Eigen's tolerance (relative to the initial preconditioned
  // residual) is relative to ‖T⁻¹b‖; the first Krylov vector is the symmetric step.
  delta = gmres.solve(rhs);
  outcome.iterations = static_cast<int>(gmres.iterations());
  outcome.residual = gmres.error();
  outcome.converged = gmres.info() == Eigen::Success && delta.allFinite();
  return outcome;
}

} // namespace formflow::solvers

namespace formflow::solvers {
namespace {

KrylovOutcome ghosted_gmres(const std::function<void(const VectorX&, VectorX&)>& apply,
                            const std::function<bool(const VectorX&, VectorX&)>& precondition,
                            const GhostedDot& dot, const VectorX& rhs, VectorX& x, Real tolerance,
                            int max_iterations) {
  KrylovOutcome outcome;
  const auto norm = [&dot](const VectorX& v) { return std::sqrt(dot(v, v)); };
  const auto failed = [&](int iterations) {
    x.setConstant(rhs.size(), std::numeric_limits<Real>::quiet_NaN());
    outcome.iterations = iterations;
    return outcome;
  };
  x = VectorX::Zero(rhs.size());
  if (norm(rhs) <= std::numeric_limits<Real>::min()) {
    outcome.converged = true;
    return outcome;
  }
  VectorX r; // from δ = 0, as Eigen's: the first Krylov vector is the symmetric step T⁻¹b
  if (!precondition(rhs, r)) return failed(0);
  const Real first_norm = norm(r);
  if (!std::isfinite(first_norm)) return failed(0);
  if (first_norm == 0) {
    outcome.converged = true;
    return outcome;
  }
  const int m = std::max(1, std::min(max_iterations, krylov_basis));
  MatrixX h = MatrixX::Zero(m + 1, m);
  VectorX g(m + 1), cosine(m), sine(m);
  std::vector<VectorX> basis;
  int iterations = 0;
  for (;;) {
    const Real beta = norm(r);
    basis.assign(1, r / beta);
    g.setZero();
    g[0] = beta;
    int k = 0;
    bool stop = false;
    while (k < m && !stop) {
      ++iterations;
      VectorX product, w;
      apply(basis[k], product);
      if (!precondition(product, w)) return failed(iterations);
      for (int i = 0; i <= k; ++i) { // modified Gram–Schmidt
        h(i, k) = dot(w, basis[i]);
        w -= h(i, k) * basis[i];
      }
      const Real w_norm = norm(w);
      h(k + 1, k) = w_norm;
      for (int i = 0; i < k; ++i) { // the earlier rotations on the new column
        const Real upper = cosine[i] * h(i, k) + sine[i] * h(i + 1, k);
        h(i + 1, k) = -sine[i] * h(i, k) + cosine[i] * h(i + 1, k);
        h(i, k) = upper;
      }
      const Real radius = std::hypot(h(k, k), h(k + 1, k));
      cosine[k] = radius > 0 ? h(k, k) / radius : 1.0;
      sine[k] = radius > 0 ? h(k + 1, k) / radius : 0.0;
      h(k, k) = radius;
      h(k + 1, k) = 0.0;
      g[k + 1] = -sine[k] * g[k];
      g[k] = cosine[k] * g[k];
      outcome.residual = std::abs(g[k + 1]) / first_norm;
      ++k;
      // w = 0: the Krylov space holds the solution (the residual above is 0).
      stop = !(outcome.residual >= tolerance) || iterations >= max_iterations || !(w_norm > 0);
      if (!stop && k < m) basis.push_back(w / w_norm);
    }
    const VectorX y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    for (int i = 0; i < k; ++i) x += y[i] * basis[i];
    if (stop) break;
    // Restart from the true preconditioned residual M⁻¹(b − J δ).
    VectorX product;
    apply(x, product);
    if (!precondition(VectorX(rhs - product), r)) return failed(iterations);
  }
  outcome.iterations = iterations;
  outcome.converged = outcome.residual < tolerance && std::isfinite(norm(x));
  return outcome;
}

} // namespace
} // namespace formflow::solvers
