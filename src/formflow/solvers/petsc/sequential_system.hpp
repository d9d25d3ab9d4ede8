// SPDX-License-Identifier: MIT
// A one-process linear system in PETSc (issue 20): formflow's matrix copied into one
// SeqAIJ matrix, or a saddle point's blocks into a MATNEST, in the unknowns PETSc solves
// for; the counterpart of DistributedSystem.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/petsc/copy_outcome.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"
#include "formflow/solvers/petsc/saddle_point_nest.hpp"
#include "formflow/solvers/petsc/value_map.hpp"

#include <petscksp.h>

#include <cstddef>
#include <memory>

namespace formflow::solvers::petsc {

class SequentialSystem {
public:
  /// Copies `input` (its lower triangle if `lower_only`) into `*matrix` as P Qᵀ K Q Pᵀ
  /// (`frames` Q, or empty; `layout` P, or empty; `n_velocity` the velocity rows, for the
  /// layout's slot value): made with its vectors on the first call and whenever the
  /// pattern changes (the old ones destroyed), otherwise the values go straight into
  /// PETSc's arrays through a ValueMap, with no copy of the matrix in between.
  CopyOutcome copy(const assembly::SparseMatrix& input, bool lower_only,
                   const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                   Index n_velocity, Mat* matrix, Vec* rhs, Vec* solution);
  /// copy() for a saddle point whose blocks come apart (LinearSolver::
  /// take_saddle_point_blocks): `velocity_lower` is A (lower triangle), `coupling` B and
  /// `pressure_block` C, which stay; `*matrix` becomes a SaddlePointNest's MATNEST and the
  /// vectors plain ones of `n_solved` rows. `frames` and `velocity_layout` are the
  /// velocity block's, and A gets `block_size`.
  CopyOutcome copy_saddle_point(const assembly::SparseMatrix& velocity_lower,
                                const assembly::SparseMatrix& coupling,
                                const assembly::SparseMatrix& pressure_block,
                                const assembly::SparseMatrix& frames,
                                const NodeBlockLayout& velocity_layout, PetscInt block_size,
                                Index n_solved, Mat* matrix, Vec* rhs, Vec* solution);

private:
  /// Whether `input` keeps the last copy's pattern; if not, the old matrix, vectors and
  /// maps are gone.
  bool keeps_pattern(const assembly::SparseMatrix& input, Mat* matrix, Vec* rhs, Vec* solution);

  ValueMap value_map_;         ///< where PETSc's values come from
  InputPattern input_pattern_; ///< the pattern of the last copy
  std::unique_ptr<SaddlePointNest> nest_;
  std::size_t output_nonzeros_ = 0; ///< the values of the SeqAIJ matrix
};

} // namespace formflow::solvers::petsc
