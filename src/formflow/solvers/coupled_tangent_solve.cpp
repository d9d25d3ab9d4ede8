// SPDX-License-Identifier: MIT
// GMRES on J = T + N, matrix free, preconditioned by the Cholesky factor of T.
#include "formflow/solvers/coupled_tangent_solve.hpp"

#include <Eigen/SparseCore>
#include <unsupported/Eigen/IterativeSolvers>

#include <algorithm>

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
  void attach(LinearSolver* factorized, const ShareSum* replicate) {
    factorized_ = factorized;
    replicate_ = replicate;
  }
  template <typename Matrix> FactorPreconditioner& analyzePattern(const Matrix&) { return *this; }
  template <typename Matrix> FactorPreconditioner& factorize(const Matrix&) { return *this; }
  template <typename Matrix> FactorPreconditioner& compute(const Matrix&) { return *this; }
  template <typename Rhs> VectorX solve(const Rhs& b) const {
    VectorX x;
    if (!factorized_->solve_whole(VectorX(b), x))
      x.setConstant(b.size(), std::numeric_limits<Real>::quiet_NaN());
    else if (replicate_ && *replicate_)
      (*replicate_)(x); // a distributed solve's ghosted result, whole for GMRES
    return x;
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
  LinearSolver* factorized_ = nullptr;
  const ShareSum* replicate_ = nullptr;
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

/// Eigen's GMRES keeps its Householder basis in a dense n × (restart + 1) matrix,
/// allocated and zeroed on every call (52 MB at 309 k dofs for restart 20). Newton
/// steps take 1–4 iterations, so a basis of 8 (one restart in the rare longer solve)
/// keeps that cost small without changing any measured step.
constexpr int krylov_basis = 8;

KrylovOutcome solve_coupled_tangent(const assembly::SparseMatrix& tangent_lower,
                                    const CouplingProduct& coupling, LinearSolver& factorized,
                                    const VectorX& rhs, VectorX& delta, Real tolerance,
                                    int max_iterations, const ShareSum& add_up_shares,
                                    const ShareSum& replicate) {
  KrylovOutcome outcome;
  const JacobianOperator jacobian(tangent_lower, coupling, add_up_shares);
  Eigen::GMRES<JacobianOperator, FactorPreconditioner> gmres;
  gmres.preconditioner().attach(&factorized, &replicate);
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
