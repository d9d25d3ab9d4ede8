// SPDX-License-Identifier: MIT
// A linear system whose ranks each hold a share (issue 20, docs/petsc.md "Distributed
// runs"): the rows numbered by owner, one MPIAIJ matrix preallocated and filled by COO
// from the shares, the right-hand side summed into its owners' rows, and the solution
// handed back ghosted: each rank gets the rows of its own cells (owned and ghosts).
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/petsc/copy_outcome.hpp"
#include "formflow/solvers/petsc/distributed_saddle_nest.hpp"
#include "formflow/solvers/petsc/distributed_saddle_point.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"
#include "formflow/solvers/petsc/value_map.hpp"

#include <petscksp.h>

#include <memory>
#include <vector>

namespace formflow::solvers::petsc {

class DistributedSystem {
public:
  DistributedSystem() = default;
  ~DistributedSystem() { clear(); }
  DistributedSystem(const DistributedSystem&) = delete;
  DistributedSystem& operator=(const DistributedSystem&) = delete;

  /// Hands this rank's `share` (its own cells' entries in the global free numbering;
  /// the ranks' shares add up to the system) to `*matrix`, in the unknowns PETSc
  /// solves for: y = Qᵀ x for the frames' matrix `frames` (empty: none), laid out node
  /// by node where `layout` is. Collective. The first call, and any after a rank's
  /// pattern changed, numbers the rows so that each rank owns a contiguous range (a row
  /// belongs to the lowest rank whose share has its diagonal), preallocates the MPIAIJ
  /// matrix from every rank's entries (MatSetPreallocationCOO: off-rank rows go to
  /// their owners) and makes `*rhs` and `*solution` (their old ones destroyed); every
  /// call then maps the share's values into the COO values through a ValueMap made
  /// once per pattern (no rotated or laid-out copy of the share per step) and hands
  /// them over with MatSetValuesCOO, which sums the ranks' duplicates. A saddle point
  /// (`n_first_solved` velocity rows of fewer) gets its fields (fields()).
  CopyOutcome copy(const assembly::SparseMatrix& share, bool symmetric_lower,
                   const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                   Index n_velocity, Index n_first_solved, Mat* matrix, Vec* rhs, Vec* solution);

  /// copy() for a saddle point whose blocks come apart (LinearSolver::
  /// take_saddle_point_blocks): `velocity_lower` is this rank's share of A (lower
  /// triangle), `coupling` and `pressure_block` its fixed shares of B and C; `*matrix`
  /// becomes a DistributedSaddleNest's MATNEST and the vectors plain MPI vectors of its
  /// rows. `frames` and `velocity_layout` are the velocity block's, and A gets
  /// `block_size`.
  CopyOutcome copy_saddle_point(const assembly::SparseMatrix& velocity_lower,
                                const assembly::SparseMatrix& coupling,
                                const assembly::SparseMatrix& pressure_block,
                                const assembly::SparseMatrix& frames,
                                const NodeBlockLayout& velocity_layout, PetscInt block_size,
                                Index n_first_solved, Mat* matrix, Vec* rhs, Vec* solution);

  /// The rows PETSc solves for (the laid-out count where a layout is).
  Index n_solved() const { return static_cast<Index>(petsc_index_.size()); }
  /// A saddle point's fields in PETSc's rows (null for one field).
  const DistributedFields* fields() const { return fields_.get(); }

  /// `target` = the sum over the ranks of their `share`s (each rank's own cells' loads,
  /// in the solved unknowns): PETSc's stash sends each entry to the rank that owns its
  /// row. Collective.
  void sum_shares(Vec target, const VectorX& share) const;
  /// `target` from `whole` (the same on every rank, in the solved unknowns): each rank
  /// writes its own rows, no message sent.
  void write_owned_rows(Vec target, const VectorX& whole) const;
  /// `solution` on the rows of this rank's share (its own cells' unknowns: those it
  /// owns and its ghosts), in the solved unknowns' order, NaN on every other row: a
  /// ghosted vector in the whole vector's numbering (the mesh is whole on every rank),
  /// whose other rows no loop may read (NonlinearProblem::replicate). Collective.
  VectorX ghosted(Vec solution) const;

private:
  void clear();
  /// Whether every rank keeps its pattern (`same_pattern` on all; collective); if not,
  /// the old matrix, vectors and numbering are gone and true is returned.
  bool start_rebuild(bool same_pattern, Mat* matrix, Vec* rhs, Vec* solution);

  std::vector<PetscInt> petsc_index_; ///< solved row (free or laid out) → PETSc's row
  /// The solution's rows of this rank's share (touched_) into ghost_values_.
  void make_ghost_scatter(Vec solution);

  std::vector<PetscInt> touched_;  ///< solved rows of this rank's share, ascending
  VecScatter to_ghosts_ = nullptr; ///< the solution → touched_'s rows on this rank
  Vec ghost_values_ = nullptr;
  ValueMap value_map_;         ///< the share's values → the COO values
  InputPattern input_pattern_; ///< the share pattern of the last copy
  std::vector<PetscScalar> coo_values_;
  std::unique_ptr<DistributedFields> fields_;
  std::unique_ptr<DistributedSaddleNest> nest_; ///< copy_saddle_point's blocks
};

} // namespace formflow::solvers::petsc
