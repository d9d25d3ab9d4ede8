// SPDX-License-Identifier: MIT
// The saddle point handed to PETSc as four blocks (MATNEST), so that fieldsplit takes
// its velocity block without copying it (issue 20: memory of the 3D saddle point).
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"
#include "formflow/solvers/petsc/value_map.hpp"

#include <petscmat.h>

#include <array>

namespace formflow::solvers::petsc {

/// [A Bᵀ; B C] as a MATNEST of four sequential AIJ matrices, in the solved unknowns
/// (P Qᵀ K Q Pᵀ: frames and node layout, as the whole AIJ matrix would have them).
/// Why: fieldsplit extracts each split's matrix with MatCreateSubMatrix, which on one AIJ
/// matrix copies the velocity block (nearly all of the saddle point's nonzeros) and
/// keeps the copy; on a MATNEST it returns the block itself. And formflow need not build
/// the whole matrix at all (assembly::SaddlePointSystem's copy of A with B beside it):
/// each refactorisation writes A's values from the assembled lower triangle through a
/// ValueMap; B and C are fixed. PETSc's own vectors stay plain (sequential, not
/// VECNEST), so the rest of the solver is unchanged.
class SaddlePointNest {
public:
  SaddlePointNest() = default;
  ~SaddlePointNest();
  SaddlePointNest(const SaddlePointNest&) = delete;
  SaddlePointNest& operator=(const SaddlePointNest&) = delete;

  /// The blocks of [A Bᵀ; B C] given apart (LinearSolver::take_saddle_point_blocks):
  /// A's pattern from `velocity_lower` (its lower triangle; values zero until fill()),
  /// `coupling` B and `pressure_block` C copied with their values, which stay. `frames`
  /// and `layout` are the velocity block's (n_v rows); A's block gets `block_size`.
  bool build_from_blocks(const assembly::SparseMatrix& velocity_lower,
                         const assembly::SparseMatrix& coupling,
                         const assembly::SparseMatrix& pressure_block,
                         const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                         PetscInt block_size);
  /// A's values from `input`, its lower triangle (the pattern build_from_blocks saw); the
  /// fixed blocks keep theirs.
  void fill(const assembly::SparseMatrix& velocity_lower);
  Mat matrix() const { return nest_; }

private:
  /// Block `b` (0: A, 1: Bᵀ, 2: B, 3: C) of `rows` × `columns` with the CSR pattern
  /// `pattern` and `values` (null: zero).
  bool make_block(int b, Index rows, Index columns, const CsrPattern& pattern, const Real* values,
                  PetscInt block_size);
  /// The MATNEST of the four blocks, the velocity's first `n_first` rows.
  bool nest(Index n_first, Index n);

  std::array<Mat, 4> blocks_{}; ///< A, Bᵀ, B, C (row-major order of the 2 × 2)
  ValueMap velocity_map_;       ///< A's values
  std::size_t velocity_values_ = 0;
  Mat nest_ = nullptr;
};

} // namespace formflow::solvers::petsc
