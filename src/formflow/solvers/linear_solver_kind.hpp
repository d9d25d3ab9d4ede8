// SPDX-License-Identifier: MIT
// The direct solvers by name (the key solver.linear).
#pragma once

namespace formflow::solvers {

/// A direct solver back-end (solvers/linear_solver_factory.cpp builds them). A new
/// back-end is one file with its make_* function plus one case in the factory and a
/// choice of the key solver.linear.
///
/// Petsc: PETSc's KSP/PC (solvers/petsc/, built with FORMFLOW_WITH_PETSC), configured by
/// solver.petsc_options; a build without it refuses the choice at validation.
enum class LinearSolverKind { Cholmod, Umfpack, Petsc };

/// How a system's matrix is handed over: the lower triangle of a symmetric positive
/// definite matrix (the velocity systems), or every entry of an indefinite one (the
/// Taylor–Hood saddle point).
enum class MatrixStorage { SymmetricLower, Full };

} // namespace formflow::solvers
