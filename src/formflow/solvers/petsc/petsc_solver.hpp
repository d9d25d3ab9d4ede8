// SPDX-License-Identifier: MIT
// The PETSc back-end of solver.linear (built with FORMFLOW_WITH_PETSC only).
#pragma once

#include "formflow/solvers/linear_solver.hpp"

#include <memory>
#include <string>

namespace formflow::solvers {

/// PETSc's KSP on one process (PETSC_COMM_SELF): the matrix copied into a sequential
/// AIJ matrix (both triangles: iterative methods need them, MUMPS' Cholesky reads the
/// upper one), options from `options` (solver.petsc_options) and then the command
/// line's PETSc options. Without options: a direct solve, KSP "preonly" with MUMPS
/// Cholesky (SymmetricLower, the SPD velocity systems) or LU (Full, the saddle point).
/// An option no PETSc object read by the first factorisation, or one PETSc refuses
/// (an unknown type), is an InputError naming solver.petsc_options (file and line
/// filled in by the caller); a failed factorisation or a diverged Krylov solve is a
/// `false` return, as for the other back-ends.
std::unique_ptr<LinearSolver> make_petsc_solver(MatrixStorage storage, const std::string& options);

} // namespace formflow::solvers
