// SPDX-License-Identifier: MIT
// The sparsity pattern of the global system, built once, and the direct map
// from each block's local matrix entries to their slots in it.
#pragma once

#include "formflow/core/types.hpp"

#include <Eigen/SparseCore>
#include <vector>

namespace formflow::assembly {

using SparseMatrix = Eigen::SparseMatrix<Real, Eigen::ColMajor, Index>;

/// A list of blocks (cells, contact faces), each a list of global dofs.
struct BlockDofs {
  std::vector<Index> offsets{0}; ///< block k owns dofs[offsets[k] .. offsets[k+1])
  std::vector<Index> dofs;
  void add(const std::vector<Index>& block_dofs) {
    dofs.insert(dofs.end(), block_dofs.begin(), block_dofs.end());
    offsets.push_back(static_cast<Index>(dofs.size()));
  }
  Index n_blocks() const { return static_cast<Index>(offsets.size()) - 1; }
  int block_size(Index block) const { return offsets[block + 1] - offsets[block]; }
};

/// The linear system K_ff u_f = F_f after eliminating the prescribed dofs, and
/// the rows K_c· of the prescribed dofs (their reactions are K_c· u).
struct LinearSystem {
  SparseMatrix matrix;        ///< K_ff, lower triangle only (symmetric)
  VectorX rhs;                ///< F_f = −K_fc u_c (+ loads)
  SparseMatrix reaction_rows; ///< K_c·, n_constrained × n_dofs
  /// F_c, loads on the prescribed rows (n_constrained): reactions are K_c· u − F_c.
  VectorX prescribed_loads;
};

/// The pattern of a compressed column-major matrix without its values: a plan keeps it
/// for the systems it makes (whose values are theirs), not a zero matrix of its own.
struct CompressedPattern {
  Index rows = 0, columns = 0;
  std::vector<Index> outer{0}, inner;
  /// The zero matrix of this pattern.
  SparseMatrix zeros() const;
  /// The storage slot of entry (row, column), which must be in the pattern.
  Index slot(Index row, Index column) const;
};

/// Precomputed scatter of symmetric local matrices into a LinearSystem. Since
/// the mesh never changes, each local entry's storage slot is found once and
/// every later assembly is a plain indexed add (no sorting, no search).
class ScatterPlan {
public:
  /// `prescribed[dof]` marks Dirichlet dofs; `blocks` are all blocks that will be scattered.
  ScatterPlan(Index n_dofs, const std::vector<bool>& prescribed, const BlockDofs& blocks);

  /// A zeroed system with the final sparsity pattern.
  LinearSystem make_system() const;
  /// Zeros the values of `system`, keeping its pattern.
  static void clear(LinearSystem& system);

  /// Adds the symmetric local matrix of `block` to `system`; prescribed values
  /// come from `prescribed_values` (full dof vector) and move to the rhs.
  void scatter(Index block, const MatrixX& local_matrix, const VectorX& prescribed_values,
               LinearSystem& system) const;

  Index n_dofs() const { return static_cast<Index>(free_index_.size()); }
  Index n_free() const { return n_free_; }
  Index n_prescribed() const { return n_dofs() - n_free_; }
  /// Free-system index of `dof`, or −1 when prescribed.
  Index free_index(Index dof) const { return free_index_[dof]; }
  /// Row of `dof` in LinearSystem::reaction_rows, or −1 when free.
  Index prescribed_index(Index dof) const { return prescribed_index_[dof]; }

  /// Full dof vector from the free solution and the prescribed values.
  VectorX expand(const VectorX& free_values, const VectorX& prescribed_values) const;

private:
  struct ReactionSlot {
    int local_row, local_column;
    Index slot;
  };
  BlockDofs blocks_;
  std::vector<Index> free_index_, prescribed_index_;
  Index n_free_ = 0;
  CompressedPattern matrix_pattern_, reaction_pattern_;
  std::vector<Index> slot_offsets_; ///< per block, into slots_
  std::vector<Index> slots_;        ///< per block: local pairs a ≤ b, slot in K_ff or −1
  std::vector<Index> prescribed_local_offsets_; ///< per block, into prescribed_local_
  std::vector<int> prescribed_local_; ///< per block: local positions of its prescribed dofs
  std::vector<Index> reaction_offsets_;
  std::vector<ReactionSlot> reaction_slots_;
};

} // namespace formflow::assembly
