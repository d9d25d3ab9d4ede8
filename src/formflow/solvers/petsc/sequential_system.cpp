// SPDX-License-Identifier: MIT
#include "formflow/solvers/petsc/sequential_system.hpp"

#include <span>
#include <type_traits>

namespace formflow::solvers::petsc {

bool SequentialSystem::keeps_pattern(const assembly::SparseMatrix& input, Mat* matrix, Vec* rhs,
                                     Vec* solution) {
  if (*matrix && input_pattern_.matches(input)) return true;
  value_map_ = {};
  input_pattern_ = {};
  nest_.reset();
  if (*matrix) MatDestroy(matrix);
  if (*rhs) VecDestroy(rhs);
  if (*solution) VecDestroy(solution);
  return false;
}

CopyOutcome SequentialSystem::copy(const assembly::SparseMatrix& input, bool lower_only,
                                   const assembly::SparseMatrix& frames,
                                   const NodeBlockLayout& layout, Index n_velocity, Mat* matrix,
                                   Vec* rhs, Vec* solution) {
  const bool rebuild = !keeps_pattern(input, matrix, rhs, solution);
  if (rebuild) {
    const CsrPattern pattern = solved_pattern(input, lower_only, frames, layout);
    const auto n = static_cast<PetscInt>(pattern.outer.size() - 1);
    // MatSeqAIJSetPreallocationCSR copies the CSR arrays into the matrix.
    static_assert(std::is_same_v<PetscInt, Index>, "PETSc's CSR indices are formflow's");
    if (MatCreate(PETSC_COMM_SELF, matrix) != 0 || MatSetSizes(*matrix, n, n, n, n) != 0 ||
        MatSetType(*matrix, MATSEQAIJ) != 0 ||
        MatSeqAIJSetPreallocationCSR(*matrix, pattern.outer.data(), pattern.inner.data(),
                                     nullptr) != 0) {
      if (*matrix) MatDestroy(matrix);
      return CopyOutcome::refused;
    }
    if (lower_only) {
      MatSetOption(*matrix, MAT_SYMMETRIC, PETSC_TRUE);
      MatSetOption(*matrix, MAT_SPD, PETSC_TRUE);
    }
    MatCreateVecs(*matrix, solution, rhs);
    value_map_ =
        ValueMap(input, lower_only, frames, layout, pattern.outer, pattern.inner, n_velocity);
    output_nonzeros_ = pattern.inner.size();
    input_pattern_ = InputPattern(input);
  }
  PetscScalar* values = nullptr;
  MatSeqAIJGetArray(*matrix, &values);
  value_map_.fill(input, std::span<Real>(values, output_nonzeros_));
  MatSeqAIJRestoreArray(*matrix, &values); // raises the state: the PC sets up anew
  return rebuild ? CopyOutcome::rebuilt : CopyOutcome::values;
}

CopyOutcome SequentialSystem::copy_saddle_point(const assembly::SparseMatrix& velocity_lower,
                                                const assembly::SparseMatrix& coupling,
                                                const assembly::SparseMatrix& pressure_block,
                                                const assembly::SparseMatrix& frames,
                                                const NodeBlockLayout& velocity_layout,
                                                PetscInt block_size, Index n_solved, Mat* matrix,
                                                Vec* rhs, Vec* solution) {
  const bool rebuild = !keeps_pattern(velocity_lower, matrix, rhs, solution);
  if (rebuild) {
    nest_ = std::make_unique<SaddlePointNest>();
    if (!nest_->build_from_blocks(velocity_lower, coupling, pressure_block, frames, velocity_layout,
                                  block_size)) {
      nest_.reset();
      return CopyOutcome::refused;
    }
    // The nest as the solver's matrix, with plain vectors (not the nest's VECNEST: the
    // solver reads and writes them as arrays).
    *matrix = nest_->matrix();
    PetscObjectReference(reinterpret_cast<PetscObject>(*matrix));
    VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(n_solved), rhs);
    VecDuplicate(*rhs, solution);
    input_pattern_ = InputPattern(velocity_lower);
  }
  nest_->fill(velocity_lower); // A alone: B and C stay
  return rebuild ? CopyOutcome::rebuilt : CopyOutcome::values;
}

} // namespace formflow::solvers::petsc
