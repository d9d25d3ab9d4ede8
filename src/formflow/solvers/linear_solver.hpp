// SPDX-License-Identifier: MIT
// Sparse SPD direct solver interface: analyse the pattern once, factorise per iteration.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/linear_solver_kind.hpp"

#include <memory>
#include <string>
#include <string_view>

namespace formflow::solvers {

/// Direct solver of K x = b for a symmetric positive definite K given by its
/// lower triangle. Failures are reported by return value, never by exception.
class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Fill-reducing ordering and symbolic factorisation of the pattern of `lower`.
  virtual bool analyze(const assembly::SparseMatrix& lower) = 0;
  /// Numeric factorisation; same pattern as analysed. False if not positive definite.
  virtual bool factorize(const assembly::SparseMatrix& lower) = 0;
  /// Solves with the last factorisation. False on failure.
  virtual bool solve(const VectorX& rhs, VectorX& solution) = 0;
  virtual std::string name() const = 0;
};

/// The key's spelling of `kind` ("cholmod", "umfpack").
std::string_view linear_solver_name(LinearSolverKind kind);

/// Whether `kind` can factorise matrices stored as `storage` (CHOLMOD LLᵀ: SPD only).
bool can_serve(LinearSolverKind kind, MatrixStorage storage);

/// The solver `kind` for matrices stored as `storage`; can_serve(kind, storage) holds.
std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind, MatrixStorage storage);

/// CHOLMOD supernodal LLᵀ through Eigen's CholmodSupport (BLAS-3 on supernodes).
std::unique_ptr<LinearSolver> make_cholmod_solver();

/// UMFPACK LU through Eigen's UmfPackSupport, for general (indefinite, e.g. the
/// saddle-point) matrices: unlike the CHOLMOD solver it takes the *full* matrix
/// (both triangles) in analyze/factorize.
std::unique_ptr<LinearSolver> make_umfpack_solver();

} // namespace formflow::solvers
