// SPDX-License-Identifier: MIT
// The saddle point of a distributed run as a MATNEST of four MPIAIJ blocks (issue 20,
// docs/petsc.md "Distributed runs"): the distributed counterpart of SaddlePointNest.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"
#include "formflow/solvers/petsc/value_map.hpp"

#include <petscmat.h>

#include <array>
#include <vector>

namespace formflow::solvers::petsc {

/// [A Bᵀ; B C] from every rank's shares of its blocks (its own cells' entries, in the
/// global free numbering; the ranks' shares add up), in the solved unknowns (frames and
/// node layout of the velocity block). Why not one MPIAIJ matrix of the whole saddle
/// point: fieldsplit would copy its velocity block (MatCreateSubMatrix), and formflow
/// would build each rank's whole share matrix (A's copy with B beside it) every step;
/// at 48 825 velocity dofs on two ranks they were about 100 MB of a rank's 580 MB heap
/// (docs/benchmarks.md "where a rank's memory goes"). Rows: the velocity's and the
/// pressure's each numbered by owner (the lowest rank whose share has the diagonal), a
/// rank's rows its velocity rows then its pressure rows, as MatCreateNest lays them out.
class DistributedSaddleNest {
public:
  DistributedSaddleNest() = default;
  ~DistributedSaddleNest();
  DistributedSaddleNest(const DistributedSaddleNest&) = delete;
  DistributedSaddleNest& operator=(const DistributedSaddleNest&) = delete;

  /// The blocks: A's pattern from `velocity_lower` (this rank's share, lower triangle;
  /// values zero until fill()), `coupling` B (n_p × n_v) and `pressure_block` C (n_p
  /// square) with their values, which stay; `frames` and `layout` are the velocity
  /// block's (n_v rows), and A gets `block_size`. Collective; false if PETSc refused.
  bool build(const assembly::SparseMatrix& velocity_lower, const assembly::SparseMatrix& coupling,
             const assembly::SparseMatrix& pressure_block, const assembly::SparseMatrix& frames,
             const NodeBlockLayout& layout, PetscInt block_size);
  /// A's values from this rank's share `velocity_lower` (build's pattern). Collective.
  bool fill(const assembly::SparseMatrix& velocity_lower);

  Mat matrix() const { return nest_; }
  /// The nest's row of every solved unknown: the velocity's (laid out, if it is), then
  /// the pressure's.
  const std::vector<PetscInt>& nest_index() const { return nest_index_; }
  /// This rank's rows of the nest.
  PetscInt owned() const { return owned_; }
  /// The solved rows (velocity, then pressure) of this rank's cells, ascending.
  const std::vector<PetscInt>& touched() const { return touched_; }

private:
  std::array<Mat, 4> blocks_{}; ///< A, Bᵀ, B, C
  Mat nest_ = nullptr;
  ValueMap velocity_map_;
  std::vector<PetscScalar> velocity_values_; ///< A's COO values
  std::vector<PetscInt> nest_index_;
  PetscInt owned_ = 0;
  std::vector<PetscInt> touched_;
};

} // namespace formflow::solvers::petsc
