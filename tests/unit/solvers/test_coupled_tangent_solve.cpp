// SPDX-License-Identifier: MIT
// GMRES around the CHOLMOD factor of T for (T + N) δ = b: solves the unsymmetric
// system to its tolerance, and costs nothing extra when N = 0.
#include "formflow/solvers/coupled_tangent_solve.hpp"

#include "support/grid_laplacian.hpp"

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace formflow::testing {
namespace {

TEST(CoupledTangentSolve, SolvesTheUnsymmetricSystemPreconditionedByTheSymmetricPart) {
  const int m = 20;
  const assembly::SparseMatrix lower = grid_laplacian_lower(m);
  const Index n = lower.rows();
  // N = c dᵀ-type rank-two unsymmetric coupling, of the size of T's smallest modes.
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  VectorX c(n), d(n), e(n), f(n), b(n);
  for (Index k = 0; k < n; ++k)
    c[k] = uniform(generator), d[k] = uniform(generator), e[k] = uniform(generator),
    f[k] = uniform(generator), b[k] = uniform(generator);
  c *= 0.3 / c.norm(), e *= 0.3 / e.norm(), d /= d.norm(), f /= f.norm();
  const solvers::CouplingProduct coupling = [&](const VectorX& x, VectorX& y) {
    y += c * d.dot(x) + e * f.dot(x);
  };
  auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(lower));
  ASSERT_TRUE(solver->factorize(lower));
  VectorX delta;
  const solvers::KrylovOutcome outcome =
      solvers::solve_coupled_tangent(lower, coupling, *solver, b, delta, 1e-10, 30);
  ASSERT_TRUE(outcome.converged);
  VectorX jacobian_delta = lower.selfadjointView<Eigen::Lower>() * delta;
  coupling(delta, jacobian_delta);
  EXPECT_LT((jacobian_delta - b).norm(), 1e-8 * b.norm());
  // T⁻¹J = I + rank two: its Krylov space has dimension ≤ 3, so ≤ 3 iterations.
  EXPECT_LE(outcome.iterations, 3);
  // The symmetric step alone is not the answer (the coupling matters here).
  VectorX symmetric_step;
  ASSERT_TRUE(solver->solve(b, symmetric_step));
  EXPECT_GT((symmetric_step - delta).norm(), 1e-3 * delta.norm());

  // N = 0: the first iterate, a multiple of T⁻¹b, already solves it.
  const solvers::CouplingProduct none = [](const VectorX&, VectorX&) {};
  const solvers::KrylovOutcome trivial =
      solvers::solve_coupled_tangent(lower, none, *solver, b, delta, 1e-10, 30);
  EXPECT_TRUE(trivial.converged);
  EXPECT_EQ(trivial.iterations, 1);
  // GMRES's first iterate is α·T⁻¹b with α fitted by least squares to b; α − 1 is
  // the round-off of T(T⁻¹b) against b, ≲ ε·κ(T). κ of the m×m Dirichlet
  // Laplacian in closed form: λ = 4 − 2cos(iπ/(m+1)) − 2cos(jπ/(m+1)), so
  // κ = (1 + cos θ)/(1 − cos θ) with θ = π/(m+1) (≈ 178 for m = 20); 10 for the
  // handful of inner products the fit takes.
  const double theta = std::acos(-1.0) / (m + 1);
  const double condition = (1 + std::cos(theta)) / (1 - std::cos(theta));
  EXPECT_LT((delta - symmetric_step).norm(),
            10 * std::numeric_limits<double>::epsilon() * condition * symmetric_step.norm());
}

/// The GMRES of ghosted vectors (a distributed run's; here with the plain inner product,
/// one process): the same answers as Eigen's, also through restarts.
TEST(CoupledTangentSolve, TheGhostedGmresSolvesItAlikeAndRestarts) {
  const int m = 12; // 144 unknowns: T⁻¹J is small enough to take its condition exactly
  const assembly::SparseMatrix lower = grid_laplacian_lower(m);
  const Index n = lower.rows();
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  // N = Σ_k c_k d_kᵀ of rank `rank`: T⁻¹J = I + rank-`rank`, a Krylov space of dimension
  // ≤ rank + 1; twelve exceeds the basis of eight, so GMRES must restart.
  const auto coupling_of_rank = [&](int rank) {
    std::vector<VectorX> c(rank, VectorX(n)), d(rank, VectorX(n));
    for (int k = 0; k < rank; ++k) {
      for (Index i = 0; i < n; ++i) c[k][i] = uniform(generator), d[k][i] = uniform(generator);
      c[k] *= 3.0 / c[k].norm();
      d[k] /= d[k].norm();
    }
    return solvers::CouplingProduct([c, d](const VectorX& x, VectorX& y) {
      for (std::size_t k = 0; k < c.size(); ++k) y += c[k] * d[k].dot(x);
    });
  };
  VectorX b(n);
  for (Index i = 0; i < n; ++i) b[i] = uniform(generator);
  auto solver = solvers::make_cholmod_solver();
  ASSERT_TRUE(solver->analyze(lower));
  ASSERT_TRUE(solver->factorize(lower));
  const solvers::GhostedDot plain = [](const VectorX& x, const VectorX& y) { return x.dot(y); };
  for (const int rank : {2, 12}) {
    const solvers::CouplingProduct coupling = coupling_of_rank(rank);
    VectorX delta;
    const solvers::KrylovOutcome outcome =
        solvers::solve_coupled_tangent(lower, coupling, *solver, b, delta, 1e-10, 40, {}, plain);
    ASSERT_TRUE(outcome.converged) << "rank " << rank;
    if (rank < 8) {
      EXPECT_LE(outcome.iterations, rank + 1) << "rank " << rank; // no restart
    } else {
      EXPECT_GT(outcome.iterations, 8) << "no restart was needed";
    }
    // ‖T⁻¹(b − Jδ)‖ ≤ 1e-10 ‖T⁻¹b‖ bounds ‖b − Jδ‖ by κ(T)·1e-10 ‖b‖ ≈ 7e-9 ‖b‖ (κ ≈ 67).
    VectorX jacobian_delta = lower.selfadjointView<Eigen::Lower>() * delta;
    coupling(delta, jacobian_delta);
    EXPECT_LT((jacobian_delta - b).norm(), 1e-7 * b.norm()) << "rank " << rank;
    // Eigen's GMRES reaches the same δ: each within κ(T⁻¹J)·1e-10 of the solution δ*
    // (relative), κ computed from T⁻¹J itself.
    VectorX eigen_delta;
    ASSERT_TRUE(solvers::solve_coupled_tangent(lower, coupling, *solver, b, eigen_delta, 1e-10, 40)
                    .converged);
    MatrixX preconditioned(n, n);
    for (Index j = 0; j < n; ++j) {
      VectorX column = lower.selfadjointView<Eigen::Lower>() * VectorX::Unit(n, j);
      coupling(VectorX::Unit(n, j), column);
      VectorX solved;
      ASSERT_TRUE(solver->solve(column, solved));
      preconditioned.col(j) = solved;
    }
    const VectorX singular = Eigen::BDCSVD<MatrixX>(preconditioned).singularValues();
    const Real condition = singular[0] / singular[n - 1];
    EXPECT_LT((delta - eigen_delta).norm(), 2 * condition * 1e-10 * eigen_delta.norm())
        << "rank " << rank << ", condition " << condition;
  }
}

} // namespace
} // namespace formflow::testing
