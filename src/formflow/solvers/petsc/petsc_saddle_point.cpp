// SPDX-License-Identifier: MIT
// Defaults and the Schur-complement matrix of the PETSc saddle-point path.
#include "formflow/solvers/petsc/petsc_saddle_point.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>

namespace formflow::solvers::petsc {

DefaultOptions::~DefaultOptions() {
  for (const std::string& name : names_) PetscOptionsClearValue(nullptr, name.c_str());
}

void DefaultOptions::set(const std::string& name, const std::string& value) {
  PetscBool given = PETSC_FALSE;
  PetscOptionsHasName(nullptr, nullptr, name.c_str(), &given);
  if (given) return;
  PetscOptionsSetValue(nullptr, name.c_str(), value.c_str());
  names_.push_back(name);
}

void set_saddle_point_defaults(KSP ksp, DefaultOptions& defaults) {
  KSPSetType(ksp, KSPFGMRES);
  // Restarts cost iterations when the count nears the restart length; 100 vectors of
  // the system's size are small beside the matrix and the AMG hierarchy.
  KSPGMRESSetRestart(ksp, 100);
  PC preconditioner = nullptr;
  KSPGetPC(ksp, &preconditioner);
  PCSetType(preconditioner, PCFIELDSPLIT);
  PCFieldSplitSetType(preconditioner, PC_COMPOSITE_SCHUR);
  // Upper block-triangular [A Bᵀ; 0 S]⁻¹: one velocity V-cycle per iteration. With
  // exact blocks FGMRES converges in two iterations; "full" costs a second V-cycle.
  PCFieldSplitSetSchurFactType(preconditioner, PC_FIELDSPLIT_SCHUR_FACT_UPPER);
  PCFieldSplitSetSchurPre(preconditioner, PC_FIELDSPLIT_SCHUR_PRE_USER, nullptr);
  // The sub-solvers exist only at PCSetUp, which reads their options: defaults there
  // go through the database.
  defaults.set("-fieldsplit_u_ksp_type", "preonly");
  // One BoomerAMG V-cycle: over three meshes its counts stayed within 2× in 2D and on
  // the 3D slab where GAMG with the rigid-body modes did not (docs/benchmarks.md).
  defaults.set("-fieldsplit_u_pc_type", "hypre");
  // HMIS coarsening with extended+i interpolation truncated to 4 entries per row: sparser
  // coarse levels than hypre's default Falgout coarsening, so a V-cycle and the hierarchy
  // cost less, for a few more iterations. 3D round quarter at h = 0.125 (48 825 dofs),
  // to convergence: CPU 178 → 101 s, peak RSS 1 533 → 1 375 MB, Krylov 372 → 402; 2D
  // paper case neutral (docs/benchmarks.md "Velocity AMG: HMIS", session 12). Read only
  // when the velocity preconditioner is BoomerAMG.
  defaults.set("-fieldsplit_u_pc_hypre_boomeramg_coarsen_type", "HMIS");
  defaults.set("-fieldsplit_u_pc_hypre_boomeramg_interp_type", "ext+i");
  defaults.set("-fieldsplit_u_pc_hypre_boomeramg_P_max", "4");
  // One forward Gauss–Seidel sweep down and one backward sweep up (the V-cycle stays
  // symmetric) instead of PETSc's symmetric sweep each way: half the smoothing work for
  // about 10 % more iterations. l1 scaling keeps the sweep convergent where a rank's
  // rows couple to another's (hypre's advice for several processes; on one, the plain
  // hybrid sweep). 3D round quarter, three exact steps: V-cycle 0.36 → 0.22 s at h = 1/12,
  // FGMRES time 74 → 52 s, counts 38 → 42 per step, 26 / 35 / 42 / 45 over h = 1/4 … 1/16
  // (docs/benchmarks.md "Loose first steps, one sweep each way", session 14).
  defaults.set("-fieldsplit_u_pc_hypre_boomeramg_relax_type_down", "l1-Gauss-Seidel");
  defaults.set("-fieldsplit_u_pc_hypre_boomeramg_relax_type_up", "backward-l1-Gauss-Seidel");
  defaults.set("-fieldsplit_p_ksp_type", "preonly");
  defaults.set("-fieldsplit_p_pc_type", "pbjacobi");
}

void copy_schur_matrix(const assembly::SparseMatrix& matrix, Index block, Mat* target) {
  using RowMatrix = Eigen::SparseMatrix<Real, Eigen::RowMajor, PetscInt>;
  RowMatrix rows = matrix;
  rows.makeCompressed();
  const auto n = static_cast<PetscInt>(rows.rows());
  if (*target) {
    PetscInt existing = 0;
    MatGetSize(*target, &existing, nullptr);
    FF_ASSERT(existing == n, "the pressure block keeps its size");
    PetscScalar* values = nullptr;
    MatSeqAIJGetArray(*target, &values);
    std::copy(rows.valuePtr(), rows.valuePtr() + rows.nonZeros(), values);
    MatSeqAIJRestoreArray(*target, &values); // raises the state: the PC sets up anew
    return;
  }
  MatCreate(PETSC_COMM_SELF, target);
  MatSetSizes(*target, n, n, n, n);
  MatSetBlockSize(*target, static_cast<PetscInt>(std::max<Index>(block, 1)));
  MatSetType(*target, MATSEQAIJ);
  MatSeqAIJSetPreallocationCSR(*target, rows.outerIndexPtr(), rows.innerIndexPtr(),
                               rows.valuePtr());
  MatSetOption(*target, MAT_SYMMETRIC, PETSC_TRUE);
}

void attach_schur_matrix(PC preconditioner, Mat pressure_matrix) {
  PCCompositeType type = PC_COMPOSITE_ADDITIVE;
  PCFieldSplitGetType(preconditioner, &type);
  if (type != PC_COMPOSITE_SCHUR) return;
  PCFieldSplitSchurPreType pre = PC_FIELDSPLIT_SCHUR_PRE_SELFP;
  Mat previous = nullptr;
  PCFieldSplitGetSchurPre(preconditioner, &pre, &previous);
  PCFieldSplitSetSchurPre(preconditioner, pre, pressure_matrix);
}

PetscErrorCode set_up_splits(PC preconditioner) {
  PetscBool fieldsplit = PETSC_FALSE;
  PetscObjectTypeCompare(reinterpret_cast<PetscObject>(preconditioner), PCFIELDSPLIT, &fieldsplit);
  if (!fieldsplit) return 0;
  PetscInt n = 0;
  KSP* splits = nullptr;
  if (const PetscErrorCode got = PCFieldSplitGetSubKSP(preconditioner, &n, &splits); got != 0)
    return got;
  PetscErrorCode first = 0;
  for (PetscInt i = 0; i < n && first == 0; ++i) first = KSPSetUp(splits[i]);
  PetscFree(splits);
  return first;
}

void compose_near_null_space(IS velocity, std::vector<Vec>& modes) {
  // Modified Gram–Schmidt, in place.
  for (std::size_t k = 0; k < modes.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      PetscScalar projection = 0;
      VecDot(modes[k], modes[j], &projection);
      VecAXPY(modes[k], -projection, modes[j]);
    }
    PetscReal norm = 0;
    VecNormalize(modes[k], &norm);
  }
  MPI_Comm communicator = MPI_COMM_NULL;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(velocity), &communicator);
  MatNullSpace space = nullptr;
  MatNullSpaceCreate(communicator, PETSC_FALSE, static_cast<PetscInt>(modes.size()), modes.data(),
                     &space);
  PetscObjectCompose(reinterpret_cast<PetscObject>(velocity), "nearnullspace",
                     reinterpret_cast<PetscObject>(space));
  MatNullSpaceDestroy(&space);
  for (Vec& mode : modes) VecDestroy(&mode);
}

} // namespace formflow::solvers::petsc
