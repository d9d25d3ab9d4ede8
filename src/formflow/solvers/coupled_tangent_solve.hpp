// SPDX-License-Identifier: MIT
// The unsymmetric Newton system (T + N) δ = b with the factorised symmetric part T
// as preconditioner: GMRES (Eigen unsupported/IterativeSolvers) around CHOLMOD.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/linear_solver.hpp"

#include <functional>

namespace formflow::solvers {

/// y += N x on free dof vectors.
using CouplingProduct = std::function<void(const VectorX& x, VectorX& y)>;
/// A distributed run's sum of the ranks' shares of a vector, in place (collective;
/// NonlinearProblem::add_up_shares). Empty on one rank.
using ShareSum = std::function<void(VectorX& values)>;
/// A distributed run's inner product of ghosted vectors (NonlinearProblem::dot). Empty
/// on one rank.
using GhostedDot = std::function<Real(const VectorX& a, const VectorX& b)>;

struct KrylovOutcome {
  bool converged = false;
  int iterations = 0;  ///< GMRES iterations = extra triangular solves
  Real residual = 0.0; ///< final ‖T⁻¹(b − Jδ)‖ / ‖T⁻¹b‖
};

/// Solves (T + N) δ = b, T the symmetric matrix given by its lower triangle and
/// already factorised in `factorized`, N applied by `coupling`. GMRES (no
/// restart) from δ = 0, left-preconditioned by T⁻¹, until ‖T⁻¹(b − Jδ)‖ ≤
/// tolerance·‖T⁻¹b‖; its first iterate is a multiple of the symmetric step T⁻¹b,
/// so with N = 0 one iteration solves it. `delta` holds the last iterate even
/// when GMRES did not reach `tolerance` within `max_iterations`.
/// Distributed (issue 20): T and N are this rank's shares, `add_up_shares` sums each
/// product T x + N x over the ranks into a ghosted vector (the rank's own cells' dofs),
/// `rhs` and every Krylov vector are ghosted alike (the preconditioner is `factorized`'s
/// solve_whole, which reads each rank's owned rows and hands back its own cells' ones),
/// and `dot` sums the inner products over the owners: the same GMRES on every rank, with
/// the same decisions, to the same δ (each rank its own cells' entries of it). Eigen's
/// GMRES cannot reduce its inner products over ranks, hence the GMRES of its own here
/// (left-preconditioned, modified Gram–Schmidt and Givens rotations, restarted like
/// Eigen's and stopped by the same measure).
KrylovOutcome solve_coupled_tangent(const assembly::SparseMatrix& tangent_lower,
                                    const CouplingProduct& coupling, LinearSolver& factorized,
                                    const VectorX& rhs, VectorX& delta, Real tolerance,
                                    int max_iterations, const ShareSum& add_up_shares = {},
                                    const GhostedDot& dot = {});

} // namespace formflow::solvers
