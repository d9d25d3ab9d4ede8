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
/// keeps the copy; on a MATNEST it returns the block itself. Each refactorisation writes
/// the four blocks' values through their ValueMaps; PETSc's own vectors stay plain
/// (sequential, not VECNEST), so the rest of the solver is unchanged.
class SaddlePointNest {
public:
  SaddlePointNest() = default;
  ~SaddlePointNest();
  SaddlePointNest(const SaddlePointNest&) = delete;
  SaddlePointNest& operator=(const SaddlePointNest&) = delete;

  /// The blocks of the whole laid-out pattern (solved_pattern), values zero until fill():
  /// the first `n_first` rows and columns are the velocity's, whose block gets
  /// `block_size` (the node layout's components, 1 without it). `input`, `lower_only`,
  /// `frames`, `layout`, `n_velocity` as for ValueMap. False if PETSc refused.
  bool build(const CsrPattern& pattern, Index n_first, PetscInt block_size,
             const assembly::SparseMatrix& input, bool lower_only,
             const assembly::SparseMatrix& frames, const NodeBlockLayout& layout, Index n_velocity);
  /// The blocks' values from `input` (the pattern build() saw).
  void fill(const assembly::SparseMatrix& input);
  Mat matrix() const { return nest_; }

private:
  std::array<Mat, 4> blocks_{}; ///< A, Bᵀ, B, C (row-major order of the 2 × 2)
  std::array<ValueMap, 4> maps_;
  std::array<std::size_t, 4> values_{};
  Mat nest_ = nullptr;
};

} // namespace formflow::solvers::petsc
