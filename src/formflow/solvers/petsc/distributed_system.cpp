// SPDX-License-Identifier: MIT
#include "formflow/solvers/petsc/distributed_system.hpp"

#include "formflow/solvers/petsc/distributed_numbering.hpp"

#include <mpi.h>

#include <limits>
#include <utility>

namespace formflow::solvers::petsc {

void DistributedSystem::clear() {
  if (to_ghosts_) VecScatterDestroy(&to_ghosts_);
  if (ghost_values_) VecDestroy(&ghost_values_);
  touched_.clear();
  fields_.reset();
  nest_.reset();
  value_map_ = {};
  input_pattern_ = {};
}

bool DistributedSystem::start_rebuild(bool same_pattern, Mat* matrix, Vec* rhs, Vec* solution) {
  // Every rank rebuilds if any rank's pattern changed: the numbering is collective.
  int rebuild = same_pattern ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &rebuild, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  if (rebuild) {
    if (*matrix) MatDestroy(matrix);
    if (*rhs) VecDestroy(rhs);
    if (*solution) VecDestroy(solution);
    clear();
  }
  return rebuild != 0;
}

CopyOutcome DistributedSystem::copy(const assembly::SparseMatrix& share, bool symmetric_lower,
                                    const assembly::SparseMatrix& frames,
                                    const NodeBlockLayout& layout, Index n_velocity,
                                    Index n_first_solved, Mat* matrix, Vec* rhs, Vec* solution) {
  const bool rebuild =
      start_rebuild(*matrix && input_pattern_.matches(share), matrix, rhs, solution);
  if (rebuild) {
    // Both triangles, row by row, in the layout's rows.
    const CsrPattern pattern = share_pattern(share, symmetric_lower, frames, layout, n_velocity);
    const auto n = static_cast<PetscInt>(pattern.outer.size() - 1);
    DistributedNumbering numbering = number_by_owner(pattern.outer, pattern.inner);
    petsc_index_ = std::move(numbering.petsc_index);
    touched_ = std::move(numbering.touched);
    const PetscInt owned = numbering.owned;
    // coo_entries reads a compressed-column pattern: given rows, its (row, column)
    // pairs come out transposed, and its sources are the pattern's value indices.
    CooEntries coo = coo_entries(pattern.outer, pattern.inner, petsc_index_,
                                 /*symmetric_lower=*/false);
    std::swap(coo.rows, coo.columns);
    if (MatCreate(PETSC_COMM_WORLD, matrix) != 0 || MatSetSizes(*matrix, owned, owned, n, n) != 0 ||
        MatSetType(*matrix, MATMPIAIJ) != 0 ||
        MatSetPreallocationCOO(*matrix, static_cast<PetscCount>(coo.rows.size()), coo.rows.data(),
                               coo.columns.data()) != 0) {
      if (*matrix) MatDestroy(matrix);
      return CopyOutcome::refused;
    }
    if (symmetric_lower) {
      MatSetOption(*matrix, MAT_SYMMETRIC, PETSC_TRUE);
      MatSetOption(*matrix, MAT_SPD, PETSC_TRUE);
    }
    MatCreateVecs(*matrix, solution, rhs);
    make_ghost_scatter(*solution);
    if (n_first_solved > 0 && n_first_solved < n) {
      // A saddle point: its fields in PETSc's rows (each rank its own).
      PetscInt low = 0, high = 0;
      MatGetOwnershipRange(*matrix, &low, &high);
      fields_ = std::make_unique<DistributedFields>(petsc_index_, low, high, n_first_solved);
    }
    value_map_ =
        ValueMap(share, symmetric_lower, frames, layout, pattern.outer, pattern.inner, n_velocity);
    input_pattern_ = InputPattern(share);
    coo_values_.assign(pattern.inner.size(), 0.0);
  }
  // The COO entries are the pattern's values in order.
  value_map_.fill(share, coo_values_);
  if (MatSetValuesCOO(*matrix, coo_values_.data(), INSERT_VALUES) != 0) {
    MatDestroy(matrix);
    return CopyOutcome::refused;
  }
  return rebuild ? CopyOutcome::rebuilt : CopyOutcome::values;
}

CopyOutcome DistributedSystem::copy_saddle_point(const assembly::SparseMatrix& velocity_lower,
                                                 const assembly::SparseMatrix& coupling,
                                                 const assembly::SparseMatrix& pressure_block,
                                                 const assembly::SparseMatrix& frames,
                                                 const NodeBlockLayout& velocity_layout,
                                                 PetscInt block_size, Index n_first_solved,
                                                 Mat* matrix, Vec* rhs, Vec* solution) {
  const bool rebuild = start_rebuild(nest_ && *matrix && input_pattern_.matches(velocity_lower),
                                     matrix, rhs, solution);
  if (rebuild) {
    nest_ = std::make_unique<DistributedSaddleNest>();
    if (!nest_->build(velocity_lower, coupling, pressure_block, frames, velocity_layout,
                      block_size)) {
      nest_.reset();
      return CopyOutcome::refused;
    }
    *matrix = nest_->matrix();
    PetscObjectReference(reinterpret_cast<PetscObject>(*matrix));
    petsc_index_ = nest_->nest_index();
    // Plain vectors of the nest's rows (not VECNEST: the solver reads and writes arrays).
    VecCreateMPI(PETSC_COMM_WORLD, nest_->owned(), PETSC_DETERMINE, solution);
    VecDuplicate(*solution, rhs);
    touched_ = nest_->touched();
    make_ghost_scatter(*solution);
    PetscInt low = 0, high = 0;
    VecGetOwnershipRange(*solution, &low, &high);
    fields_ = std::make_unique<DistributedFields>(petsc_index_, low, high, n_first_solved);
    input_pattern_ = InputPattern(velocity_lower);
  }
  if (!nest_->fill(velocity_lower)) {
    MatDestroy(matrix);
    return CopyOutcome::refused;
  }
  return rebuild ? CopyOutcome::rebuilt : CopyOutcome::values;
}

void DistributedSystem::sum_shares(Vec target, const VectorX& share) const {
  VecSet(target, 0.0);
  for (Index i = 0; i < share.size(); ++i)
    if (share[i] != 0.0) VecSetValue(target, petsc_index_[i], share[i], ADD_VALUES);
  VecAssemblyBegin(target);
  VecAssemblyEnd(target);
}

void DistributedSystem::write_owned_rows(Vec target, const VectorX& whole) const {
  PetscInt low = 0, high = 0;
  VecGetOwnershipRange(target, &low, &high);
  PetscScalar* values = nullptr;
  VecGetArray(target, &values);
  for (Index i = 0; i < whole.size(); ++i)
    if (const PetscInt row = petsc_index_[i]; row >= low && row < high)
      values[row - low] = whole[i];
  VecRestoreArray(target, &values);
}

void DistributedSystem::make_ghost_scatter(Vec solution) {
  std::vector<PetscInt> rows(touched_.size());
  for (std::size_t k = 0; k < touched_.size(); ++k) rows[k] = petsc_index_[touched_[k]];
  IS from = nullptr;
  ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(rows.size()), rows.data(),
                  PETSC_COPY_VALUES, &from);
  VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(rows.size()), &ghost_values_);
  VecScatterCreate(solution, from, ghost_values_, nullptr, &to_ghosts_);
  ISDestroy(&from);
}

VectorX DistributedSystem::ghosted(Vec solution) const {
  // The rank's own cells' rows only (owned and ghosts): its loops read no other (the
  // contact state and the integrals are exchanged or summed over the ranks), so the
  // traffic is the partition's interface, not the whole solution to every rank.
  VecScatterBegin(to_ghosts_, solution, ghost_values_, INSERT_VALUES, SCATTER_FORWARD);
  VecScatterEnd(to_ghosts_, solution, ghost_values_, INSERT_VALUES, SCATTER_FORWARD);
  const PetscScalar* result = nullptr;
  VecGetArrayRead(ghost_values_, &result);
  VectorX solved = VectorX::Constant(n_solved(), std::numeric_limits<Real>::quiet_NaN());
  for (std::size_t k = 0; k < touched_.size(); ++k) solved[touched_[k]] = result[k];
  VecRestoreArrayRead(ghost_values_, &result);
  return solved;
}

} // namespace formflow::solvers::petsc
