// SPDX-License-Identifier: MIT
// Owner-contiguous numbering of a distributed system's free dofs, and its COO entries.
#include "formflow/solvers/petsc/distributed_numbering.hpp"

#include "formflow/core/error.hpp"

#include <mpi.h>

namespace formflow::solvers::petsc {

DistributedNumbering number_by_owner(const std::vector<PetscInt>& outer,
                                     const std::vector<PetscInt>& inner) {
  const auto n = static_cast<PetscInt>(outer.size()) - 1;
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  // Owner of dof i: the lowest rank whose share has the diagonal entry (i, i).
  std::vector<int> owner(static_cast<std::size_t>(n), size);
  for (PetscInt column = 0; column < n; ++column)
    for (auto k = outer[column]; k < outer[column + 1]; ++k)
      if (inner[k] == column) owner[column] = rank;
  DistributedNumbering numbering;
  for (PetscInt i = 0; i < n; ++i)
    if (owner[i] == rank) numbering.touched.push_back(i);
  MPI_Allreduce(MPI_IN_PLACE, owner.data(), static_cast<int>(n), MPI_INT, MPI_MIN,
                PETSC_COMM_WORLD);
  std::vector<PetscInt> first(static_cast<std::size_t>(size) + 1, 0);
  for (const int o : owner) {
    FF_ASSERT(o < size, "every free dof is a dof of some rank's cells");
    ++first[o + 1];
  }
  for (int r = 0; r < size; ++r) first[r + 1] += first[r];
  std::vector<PetscInt> next(first.begin(), first.end() - 1);
  numbering.petsc_index.resize(static_cast<std::size_t>(n));
  for (PetscInt i = 0; i < n; ++i) numbering.petsc_index[i] = next[owner[i]]++;
  numbering.owned = first[rank + 1] - first[rank];
  return numbering;
}

CooEntries coo_entries(const std::vector<PetscInt>& outer, const std::vector<PetscInt>& inner,
                       const std::vector<PetscInt>& petsc_index, bool symmetric_lower) {
  CooEntries entries;
  const auto n = static_cast<PetscInt>(outer.size()) - 1;
  for (PetscInt column = 0; column < n; ++column)
    for (auto k = outer[column]; k < outer[column + 1]; ++k) {
      const PetscInt row = inner[k];
      entries.rows.push_back(petsc_index[row]);
      entries.columns.push_back(petsc_index[column]);
      entries.source.push_back(k);
      if (symmetric_lower && row != column) {
        entries.rows.push_back(petsc_index[column]);
        entries.columns.push_back(petsc_index[row]);
        entries.source.push_back(k);
      }
    }
  return entries;
}

} // namespace formflow::solvers::petsc
