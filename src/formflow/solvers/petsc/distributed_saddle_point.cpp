// SPDX-License-Identifier: MIT
// The fields, Schur matrix, near-null space and frames of a distributed saddle point.
#include "formflow/solvers/petsc/distributed_saddle_point.hpp"

#include "formflow/core/error.hpp"
#include "formflow/solvers/petsc/petsc_saddle_point.hpp"

#include <mpi.h>

#include <algorithm>

namespace formflow::solvers::petsc {

DistributedFields::DistributedFields(const std::vector<PetscInt>& petsc_index, PetscInt low,
                                     PetscInt high, Index n_first) {
  const auto n = static_cast<Index>(petsc_index.size());
  std::vector<PetscInt> velocity_rows, pressure_rows;
  std::vector<Index> owned_pressure_dofs;
  // petsc_index numbers a rank's dofs in dof order: the lists come out ascending.
  for (Index i = 0; i < n; ++i) {
    const PetscInt row = petsc_index[i];
    if (row < low || row >= high) continue;
    if (i < n_first) {
      velocity_rows.push_back(row);
      owned_velocity_dofs_.push_back(i);
    } else {
      pressure_rows.push_back(row);
      owned_pressure_dofs.push_back(i - n_first);
    }
  }
  FF_ASSERT(std::is_sorted(velocity_rows.begin(), velocity_rows.end()) &&
                std::is_sorted(pressure_rows.begin(), pressure_rows.end()),
            "owner-contiguous rows in dof order");
  ISCreateGeneral(PETSC_COMM_WORLD, static_cast<PetscInt>(velocity_rows.size()),
                  velocity_rows.data(), PETSC_COPY_VALUES, &velocity_);
  ISCreateGeneral(PETSC_COMM_WORLD, static_cast<PetscInt>(pressure_rows.size()),
                  pressure_rows.data(), PETSC_COPY_VALUES, &pressure_);
  owned_pressure_ = static_cast<PetscInt>(pressure_rows.size());
  // The "p" split's rows: the lower ranks' pressure rows first, then this rank's.
  PetscInt offset = 0;
  MPI_Exscan(&owned_pressure_, &offset, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) offset = 0; // MPI_Exscan leaves rank 0's result undefined
  pressure_row_.assign(static_cast<std::size_t>(n - n_first), -1);
  for (std::size_t k = 0; k < owned_pressure_dofs.size(); ++k)
    pressure_row_[owned_pressure_dofs[k]] = offset + static_cast<PetscInt>(k);
  // Every rank learns every pressure dof's row (each is owned once: the largest is it).
  MPI_Allreduce(MPI_IN_PLACE, pressure_row_.data(), static_cast<int>(pressure_row_.size()),
                MPIU_INT, MPI_MAX, PETSC_COMM_WORLD);
}

DistributedFields::~DistributedFields() {
  if (velocity_) ISDestroy(&velocity_);
  if (pressure_) ISDestroy(&pressure_);
}

void copy_distributed_schur_matrix(const assembly::SparseMatrix& share,
                                   const DistributedFields& fields, Index block, Mat* target) {
  const std::vector<PetscInt>& row_of = fields.pressure_row();
  FF_ASSERT(share.rows() == static_cast<Index>(row_of.size()) && share.isCompressed(),
            "a compressed share of the pressure block");
  const auto block_size = static_cast<PetscInt>(std::max<Index>(block, 1));
  if (!*target) {
    // Not COO preallocation: PETSc 3.18's MatSetPreallocationCOO leaves the diagonal
    // part's block size at 1, and pbjacobi then inverts 1 × 1 blocks but applies
    // block-size ones (NaN seen). Each row has its cell block in the diagonal part (the
    // rank owns its cells' pressure dofs); the off-diagonal room is for safety only.
    MatCreate(PETSC_COMM_WORLD, target);
    MatSetSizes(*target, fields.owned_pressure(), fields.owned_pressure(), PETSC_DETERMINE,
                PETSC_DETERMINE);
    MatSetBlockSize(*target, block_size); // pbjacobi inverts the cell blocks
    MatSetType(*target, MATMPIAIJ);
    MatMPIAIJSetPreallocation(*target, block_size, nullptr, block_size, nullptr);
    MatSetOption(*target, MAT_SYMMETRIC, PETSC_TRUE);
  } else {
    MatZeroEntries(*target);
  }
  for (Index column = 0; column < share.outerSize(); ++column)
    for (auto k = share.outerIndexPtr()[column]; k < share.outerIndexPtr()[column + 1]; ++k)
      MatSetValue(*target, row_of[share.innerIndexPtr()[k]], row_of[column], share.valuePtr()[k],
                  ADD_VALUES);
  // Raises the state: the PC sets up anew.
  MatAssemblyBegin(*target, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(*target, MAT_FINAL_ASSEMBLY);
}

void attach_distributed_near_null_space(const std::vector<VectorX>& modes,
                                        const DistributedFields& fields) {
  if (modes.empty()) return;
  const std::vector<Index>& owned = fields.owned_velocity_dofs();
  std::vector<Vec> vectors(modes.size());
  for (std::size_t m = 0; m < modes.size(); ++m) {
    VecCreateMPI(PETSC_COMM_WORLD, static_cast<PetscInt>(owned.size()), PETSC_DETERMINE,
                 &vectors[m]);
    PetscScalar* entries = nullptr;
    VecGetArray(vectors[m], &entries);
    for (std::size_t k = 0; k < owned.size(); ++k) entries[k] = modes[m][owned[k]];
    VecRestoreArray(vectors[m], &entries);
  }
  compose_near_null_space(fields.velocity(), vectors);
}

} // namespace formflow::solvers::petsc
