// SPDX-License-Identifier: MIT
// A saddle point solved on several ranks (issue 20, docs/petsc.md "Distributed runs"):
// its fields, the Schur-complement matrix and the velocity's near-null space in PETSc's
// distributed rows.
#pragma once

#include "formflow/assembly/local_frame.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"

#include <petscksp.h>

#include <vector>

namespace formflow::solvers::petsc {

/// The velocity ("u") and pressure ("p") fields of a distributed saddle point whose free
/// dofs [0, n_first) are the velocity's and [n_first, n) the pressure's: each rank lists
/// its own PETSc rows (petsc_index, owner-contiguous: distributed_numbering.hpp) of either
/// field, ascending, as fieldsplit wants them. A split's matrix numbers its rows by the
/// concatenation of the ranks' lists; `pressure_row` is that number for every pressure dof
/// (on every rank; collective), the rows of the Schur-complement matrix.
class DistributedFields {
public:
  DistributedFields(const std::vector<PetscInt>& petsc_index, PetscInt low, PetscInt high,
                    Index n_first);
  ~DistributedFields();
  DistributedFields(const DistributedFields&) = delete;
  DistributedFields& operator=(const DistributedFields&) = delete;

  IS velocity() const { return velocity_; }
  IS pressure() const { return pressure_; }
  /// The free velocity dofs whose rows this rank owns, in the "u" split's order.
  const std::vector<Index>& owned_velocity_dofs() const { return owned_velocity_dofs_; }
  PetscInt owned_pressure() const { return owned_pressure_; }
  /// Pressure dof (0-based within the pressure) → row of the "p" split.
  const std::vector<PetscInt>& pressure_row() const { return pressure_row_; }

private:
  IS velocity_ = nullptr, pressure_ = nullptr;
  std::vector<Index> owned_velocity_dofs_;
  PetscInt owned_pressure_ = 0;
  std::vector<PetscInt> pressure_row_;
};

/// The Schur complement's preconditioning matrix as MPIAIJ in the "p" split's rows, from
/// this rank's share (`share`: n_p square, the own cells' blocks; the ranks' shares add
/// up): made and preallocated by COO on the first call (`*target` null), its values
/// handed over on later ones (the share keeps its pattern). `block`: the cell block size
/// (each rank owns whole cells' pressure dofs, so its rows are whole blocks).
void copy_distributed_schur_matrix(const assembly::SparseMatrix& share,
                                   const DistributedFields& fields, Index block, Mat* target);

/// The velocity block's near-null space (rigid-body modes over the free velocity dofs,
/// whole on every rank, already in the unknowns PETSc solves for) as vectors of the "u"
/// split's layout, orthonormalised, composed on its IS as "nearnullspace" (fieldsplit gives
/// it to the split's matrix, which GAMG reads).
void attach_distributed_near_null_space(const std::vector<VectorX>& modes,
                                        const DistributedFields& fields);

} // namespace formflow::solvers::petsc
