// SPDX-License-Identifier: MIT
// How a distributed system's free dofs become PETSc rows, and a share's COO entries.
#pragma once

#include "formflow/core/types.hpp"

#include <petscsys.h>

#include <vector>

namespace formflow::solvers::petsc {

/// PETSc's rows for the free dofs of a system whose ranks each hold a share (the entries
/// of their own cells): dof i belongs to the lowest rank whose share has its diagonal,
/// and each rank owns a contiguous range of rows, in dof order within it. Collective
/// (one MPI_Allreduce of an integer per dof). `outer`, `inner`: this rank's share's
/// compressed-column pattern (n + 1 and nnz entries).
struct DistributedNumbering {
  std::vector<PetscInt> petsc_index; ///< free dof → PETSc's row
  PetscInt owned = 0;                ///< rows of this rank
  /// The dofs whose diagonal this rank's share has (its own cells' dofs: the ones it
  /// owns and its ghosts), ascending: the rows a solution is handed back on.
  std::vector<PetscInt> touched;
};
DistributedNumbering number_by_owner(const std::vector<PetscInt>& outer,
                                     const std::vector<PetscInt>& inner);

/// The share's entries as COO triplets in PETSc's rows: both triangles of a symmetric
/// matrix stored by its lower one (`symmetric_lower`), and for each entry the index of
/// its value in the share (`source`).
struct CooEntries {
  std::vector<PetscInt> rows, columns;
  std::vector<Index> source;
};
CooEntries coo_entries(const std::vector<PetscInt>& outer, const std::vector<PetscInt>& inner,
                       const std::vector<PetscInt>& petsc_index, bool symmetric_lower);

} // namespace formflow::solvers::petsc
