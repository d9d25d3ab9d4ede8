// SPDX-License-Identifier: MIT
// The iterative saddle-point path of the PETSc back-end (issue 20): FGMRES with a
// fieldsplit Schur preconditioner, algebraic multigrid on the velocity block and the
// viscosity-scaled pressure mass for the Schur complement.
#pragma once

#include "formflow/assembly/sparsity.hpp"

#include <petscksp.h>

#include <string>
#include <utility>
#include <vector>

namespace formflow::solvers::petsc {

/// Options put into the database as defaults: each only where neither the case nor
/// the command line gave it, and removed again when the object ends (the next case
/// starts clean). They are not the user's, so the unused-option check ignores them.
class DefaultOptions {
public:
  DefaultOptions() = default;
  ~DefaultOptions();
  DefaultOptions(const DefaultOptions&) = delete;
  DefaultOptions& operator=(const DefaultOptions&) = delete;
  /// Sets `name` (with its '-') to `value` unless the database has it already.
  void set(const std::string& name, const std::string& value);

private:
  std::vector<std::string> names_;
};

/// The default solver of a saddle point whose pressure preconditioner is block diagonal
/// (a discontinuous pressure's cells), set on `ksp` before KSPSetFromOptions so that
/// the options database overrides any of it: FGMRES (restart 100) outside, since the
/// inner solves are inexact; PCFIELDSPLIT Schur with the upper block-triangular
/// factorisation and the user's matrix (the viscosity-scaled pressure mass) for the
/// Schur complement, inverted exactly by point-block Jacobi on the cell blocks; one
/// BoomerAMG V-cycle on the velocity block (`-fieldsplit_u_pc_type gamg` uses the
/// rigid-body modes that the split's IS carries as its near-null space).
void set_saddle_point_defaults(KSP ksp, DefaultOptions& defaults);

/// `matrix` (square, both triangles, column-major Eigen) as a sequential AIJ matrix with
/// block size `block` (1 if 0): made on the first call (`*target` null), its values
/// copied in place later (same pattern).
void copy_schur_matrix(const assembly::SparseMatrix& matrix, Index block, Mat* target);

/// Gives `pressure_matrix` to a PCFIELDSPLIT of Schur type as the preconditioning
/// matrix of its Schur complement, keeping the Schur preconditioner type the options
/// chose (the matrix is read when that type is "user").
void attach_schur_matrix(PC preconditioner, Mat pressure_matrix);

/// Sets up a PCFIELDSPLIT's sub-solvers now (after PCSetUp), which PETSc would do at
/// their first application: they read their options (-fieldsplit_u_mg_levels_*, ...)
/// here, so that the unused-option check after the first factorisation sees them read.
/// Nothing for another PC type. Returns the first failed setup's error code (0: none).
PetscErrorCode set_up_splits(PC preconditioner);

/// The velocity split's near-null space: `modes` (vectors of its layout, one process's
/// or distributed) orthonormalised (MatNullSpaceCreate wants an orthonormal basis) and
/// composed on `velocity`, the split's index set, as "nearnullspace" (fieldsplit hands it
/// to the split's matrix, which GAMG reads); the vectors are destroyed.
void compose_near_null_space(IS velocity, std::vector<Vec>& modes);

} // namespace formflow::solvers::petsc
