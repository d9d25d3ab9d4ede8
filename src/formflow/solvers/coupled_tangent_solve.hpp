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
KrylovOutcome solve_coupled_tangent(const assembly::SparseMatrix& tangent_lower,
                                    const CouplingProduct& coupling, LinearSolver& factorized,
                                    const VectorX& rhs, VectorX& delta, Real tolerance,
                                    int max_iterations);

} // namespace formflow::solvers
