// SPDX-License-Identifier: MIT
// The direct solvers by name (the key solver.linear).
#pragma once

namespace formflow::solvers {

/// A direct solver back-end (solvers/linear_solver_factory.cpp builds them). A new
/// back-end is one file with its make_* function plus one case in the factory and a
/// choice of the key solver.linear.
enum class LinearSolverKind { Cholmod, Umfpack };

/// How a system's matrix is handed over: the lower triangle of a symmetric positive
/// definite matrix (the velocity systems), or every entry of an indefinite one (the
/// Taylor–Hood saddle point).
enum class MatrixStorage { SymmetricLower, Full };

} // namespace formflow::solvers
