// SPDX-License-Identifier: MIT
#include "formflow/solvers/petsc/distributed_saddle_nest.hpp"

#include "formflow/core/error.hpp"
#include "formflow/solvers/petsc/distributed_numbering.hpp"
#include "formflow/solvers/petsc/framed_coupling.hpp"

#include <mpi.h>

#include <algorithm>
#include <utility>

namespace formflow::solvers::petsc {

namespace {

/// Each rank's count of owned rows, gathered: first[r] is rank r's first row.
std::vector<PetscInt> first_rows(PetscInt owned) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  std::vector<PetscInt> first(static_cast<std::size_t>(size) + 1, 0);
  MPI_Allgather(&owned, 1, MPIU_INT, first.data() + 1, 1, MPIU_INT, PETSC_COMM_WORLD);
  for (int r = 0; r < size; ++r) first[r + 1] += first[r];
  return first;
}

/// The rank whose range of `first` holds `row`.
int owner_of(const std::vector<PetscInt>& first, PetscInt row) {
  return static_cast<int>(std::upper_bound(first.begin(), first.end(), row) - first.begin()) - 1;
}

/// An MPIAIJ block of `rows` × `columns` local rows and columns, preallocated by COO.
bool make_block(PetscInt rows, PetscInt columns, PetscInt block_size,
                std::vector<PetscInt>& coo_rows, std::vector<PetscInt>& coo_columns, Mat* block) {
  if (MatCreate(PETSC_COMM_WORLD, block) != 0 ||
      MatSetSizes(*block, rows, columns, PETSC_DETERMINE, PETSC_DETERMINE) != 0 ||
      (block_size > 1 && MatSetBlockSize(*block, block_size) != 0) ||
      MatSetType(*block, MATMPIAIJ) != 0 ||
      MatSetPreallocationCOO(*block, static_cast<PetscCount>(coo_rows.size()), coo_rows.data(),
                             coo_columns.data()) != 0)
    return false;
  return true;
}

} // namespace

DistributedSaddleNest::~DistributedSaddleNest() {
  if (nest_) MatDestroy(&nest_);
  for (Mat& block : blocks_)
    if (block) MatDestroy(&block);
}

bool DistributedSaddleNest::build(const assembly::SparseMatrix& velocity_lower,
                                  const assembly::SparseMatrix& coupling,
                                  const assembly::SparseMatrix& pressure_block,
                                  const assembly::SparseMatrix& frames,
                                  const NodeBlockLayout& layout, PetscInt block_size) {
  const Index n_v = velocity_lower.rows(), n_p = pressure_block.rows();
  FF_ASSERT(coupling.rows() == n_p && coupling.cols() == n_v, "B is n_p × n_v");
  // The velocity: A's share pattern in the solved rows, numbered by owner.
  const CsrPattern a = share_pattern(velocity_lower, true, frames, layout, n_v);
  DistributedNumbering velocity = number_by_owner(a.outer, a.inner);
  // The pressure dofs of this rank's cells: those its B or C share touches (a
  // discontinuous pressure belongs to one cell, so to one rank), numbered by owner
  // through a diagonal pattern of them.
  std::vector<bool> touched(static_cast<std::size_t>(n_p), false);
  for (Index column = 0; column < coupling.outerSize(); ++column)
    for (assembly::SparseMatrix::InnerIterator it(coupling, column); it; ++it)
      touched[it.row()] = true;
  for (Index column = 0; column < pressure_block.outerSize(); ++column)
    for (assembly::SparseMatrix::InnerIterator it(pressure_block, column); it; ++it)
      touched[it.row()] = touched[column] = true;
  std::vector<PetscInt> diagonal_outer{0}, diagonal_inner;
  for (Index i = 0; i < n_p; ++i) {
    if (touched[i]) diagonal_inner.push_back(i);
    diagonal_outer.push_back(static_cast<PetscInt>(diagonal_inner.size()));
  }
  DistributedNumbering pressure = number_by_owner(diagonal_outer, diagonal_inner);

  // The nest's rows: rank r's velocity rows, then its pressure rows.
  const std::vector<PetscInt> first_velocity = first_rows(velocity.owned);
  const std::vector<PetscInt> first_pressure = first_rows(pressure.owned);
  const auto nest_row = [&](PetscInt row, const std::vector<PetscInt>& first, bool is_pressure) {
    const int r = owner_of(first, row);
    return first_velocity[r] + first_pressure[r] +
           (is_pressure ? first_velocity[r + 1] - first_velocity[r] : 0) + (row - first[r]);
  };
  const auto n_solved_velocity = static_cast<Index>(a.outer.size()) - 1;
  nest_index_.resize(static_cast<std::size_t>(n_solved_velocity + n_p));
  for (Index i = 0; i < n_solved_velocity; ++i)
    nest_index_[i] = nest_row(velocity.petsc_index[i], first_velocity, false);
  for (Index i = 0; i < n_p; ++i)
    nest_index_[n_solved_velocity + i] = nest_row(pressure.petsc_index[i], first_pressure, true);
  owned_ = velocity.owned + pressure.owned;
  touched_ = velocity.touched;
  for (const PetscInt i : pressure.touched) touched_.push_back(n_solved_velocity + i);

  // A: COO on its pattern (row by row), values from the share through a ValueMap.
  std::vector<PetscInt> rows, columns;
  for (Index row = 0; row < n_solved_velocity; ++row)
    for (Index k = a.outer[row]; k < a.outer[row + 1]; ++k) {
      rows.push_back(velocity.petsc_index[row]);
      columns.push_back(velocity.petsc_index[a.inner[k]]);
    }
  if (!make_block(velocity.owned, velocity.owned, block_size, rows, columns, &blocks_[0]))
    return false;
  // PETSc keeps its own maps of them: ours go before the next blocks' are made.
  std::vector<PetscInt>().swap(rows);
  std::vector<PetscInt>().swap(columns);
  velocity_map_ = ValueMap(velocity_lower, true, frames, layout, a.outer, a.inner, n_v);
  velocity_values_.assign(a.inner.size(), 0.0);
  MatSetOption(blocks_[0], MAT_SYMMETRIC, PETSC_TRUE);

  // Bᵀ in the solved velocity rows, P Qᵀ Bᵀ, and B, its transpose: fixed values.
  std::vector<PetscInt> upper_rows, upper_columns;
  std::vector<PetscScalar> upper_values;
  for (const Eigen::Triplet<Real, Index>& entry : framed_coupling(coupling, frames, layout)) {
    upper_rows.push_back(velocity.petsc_index[entry.row()]);
    upper_columns.push_back(pressure.petsc_index[entry.col()]);
    upper_values.push_back(entry.value());
  }
  std::vector<PetscInt> lower_rows = upper_columns, lower_columns = upper_rows;
  const std::vector<PetscScalar> lower_values = upper_values;
  // C with every touched diagonal entry (zero where C has none, as with d = 0):
  // fieldsplit's Schur complement reads the block, which must not be an empty matrix.
  std::vector<PetscInt> c_rows, c_columns;
  std::vector<PetscScalar> c_values;
  for (Index column = 0; column < pressure_block.outerSize(); ++column)
    for (assembly::SparseMatrix::InnerIterator it(pressure_block, column); it; ++it) {
      c_rows.push_back(pressure.petsc_index[it.row()]);
      c_columns.push_back(pressure.petsc_index[column]);
      c_values.push_back(it.value());
    }
  for (Index i = 0; i < n_p; ++i)
    if (touched[i]) {
      c_rows.push_back(pressure.petsc_index[i]);
      c_columns.push_back(pressure.petsc_index[i]);
      c_values.push_back(0.0);
    }
  if (!make_block(velocity.owned, pressure.owned, 1, upper_rows, upper_columns, &blocks_[1]) ||
      MatSetValuesCOO(blocks_[1], upper_values.data(), INSERT_VALUES) != 0 ||
      !make_block(pressure.owned, velocity.owned, 1, lower_rows, lower_columns, &blocks_[2]) ||
      MatSetValuesCOO(blocks_[2], lower_values.data(), INSERT_VALUES) != 0 ||
      !make_block(pressure.owned, pressure.owned, 1, c_rows, c_columns, &blocks_[3]) ||
      MatSetValuesCOO(blocks_[3], c_values.data(), INSERT_VALUES) != 0)
    return false;
  return MatCreateNest(PETSC_COMM_WORLD, 2, nullptr, 2, nullptr, blocks_.data(), &nest_) == 0;
}

bool DistributedSaddleNest::fill(const assembly::SparseMatrix& velocity_lower) {
  velocity_map_.fill(velocity_lower, velocity_values_);
  if (MatSetValuesCOO(blocks_[0], velocity_values_.data(), INSERT_VALUES) != 0) return false;
  // The nest's own state: the outer preconditioner sets up anew when it has risen.
  MatAssemblyBegin(nest_, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(nest_, MAT_FINAL_ASSEMBLY);
  return true;
}

} // namespace formflow::solvers::petsc
