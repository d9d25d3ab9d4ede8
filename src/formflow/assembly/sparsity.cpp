// SPDX-License-Identifier: MIT
// Sparsity pattern and scatter slots of the global system.
#include "formflow/assembly/sparsity.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>

namespace formflow::assembly {

namespace {

CompressedPattern pattern_from(Index rows, Index columns,
                               const std::vector<Eigen::Triplet<Real, Index>>& entries) {
  SparseMatrix matrix(rows, columns);
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  CompressedPattern pattern{rows, columns, {}, {}};
  pattern.outer.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + columns + 1);
  pattern.inner.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros());
  return pattern;
}

} // namespace

SparseMatrix CompressedPattern::zeros() const {
  SparseMatrix matrix(rows, columns);
  matrix.resizeNonZeros(static_cast<Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), matrix.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), matrix.innerIndexPtr());
  std::fill_n(matrix.valuePtr(), inner.size(), 0.0);
  return matrix;
}

Index CompressedPattern::slot(Index row, Index column) const {
  const Index* begin = inner.data() + outer[column];
  const Index* end = inner.data() + outer[column + 1];
  const Index* found = std::lower_bound(begin, end, row);
  FF_ASSERT(found != end && *found == row, "entry missing from the sparsity pattern");
  return static_cast<Index>(found - inner.data());
}

ScatterPlan::ScatterPlan(Index n_dofs, const std::vector<bool>& prescribed, const BlockDofs& blocks)
    : blocks_(blocks), free_index_(n_dofs, -1), prescribed_index_(n_dofs, -1) {
  Index n_prescribed = 0;
  for (Index dof = 0; dof < n_dofs; ++dof)
    (prescribed[dof] ? prescribed_index_[dof] = n_prescribed++ : free_index_[dof] = n_free_++);

  std::vector<Eigen::Triplet<Real, Index>> matrix_entries, reaction_entries;
  for (Index block = 0; block < blocks.n_blocks(); ++block) {
    const Index* dofs = blocks.dofs.data() + blocks.offsets[block];
    const int n = blocks.block_size(block);
    for (int a = 0; a < n; ++a) {
      const Index row_free = free_index_[dofs[a]], row_prescribed = prescribed_index_[dofs[a]];
      for (int b = 0; b < n; ++b) {
        const Index column_free = free_index_[dofs[b]];
        if (row_free >= 0 && column_free >= row_free)
          matrix_entries.emplace_back(column_free, row_free, 0.0);
        if (row_prescribed >= 0) reaction_entries.emplace_back(row_prescribed, dofs[b], 0.0);
      }
    }
  }
  matrix_pattern_ = pattern_from(n_free_, n_free_, matrix_entries);
  reaction_pattern_ = pattern_from(n_prescribed, n_dofs, reaction_entries);

  slot_offsets_.push_back(0);
  reaction_offsets_.push_back(0);
  prescribed_local_offsets_.push_back(0);
  for (Index block = 0; block < blocks.n_blocks(); ++block) {
    const Index* dofs = blocks.dofs.data() + blocks.offsets[block];
    const int n = blocks.block_size(block);
    for (int b = 0; b < n; ++b)
      if (free_index_[dofs[b]] < 0) prescribed_local_.push_back(b);
    prescribed_local_offsets_.push_back(static_cast<Index>(prescribed_local_.size()));
    for (int a = 0; a < n; ++a) {
      for (int b = a; b < n; ++b) {
        const Index i = free_index_[dofs[a]], j = free_index_[dofs[b]];
        slots_.push_back(i >= 0 && j >= 0 ? matrix_pattern_.slot(std::max(i, j), std::min(i, j))
                                          : -1);
      }
      if (prescribed_index_[dofs[a]] >= 0)
        for (int b = 0; b < n; ++b)
          reaction_slots_.push_back(
              {a, b, reaction_pattern_.slot(prescribed_index_[dofs[a]], dofs[b])});
    }
    slot_offsets_.push_back(static_cast<Index>(slots_.size()));
    reaction_offsets_.push_back(static_cast<Index>(reaction_slots_.size()));
  }
}

LinearSystem ScatterPlan::make_system() const {
  LinearSystem system{matrix_pattern_.zeros(), VectorX::Zero(n_free_), reaction_pattern_.zeros(),
                      VectorX::Zero(n_prescribed())};
  clear(system);
  return system;
}

void ScatterPlan::clear(LinearSystem& system) {
  std::fill_n(system.matrix.valuePtr(), system.matrix.nonZeros(), 0.0);
  std::fill_n(system.reaction_rows.valuePtr(), system.reaction_rows.nonZeros(), 0.0);
  system.rhs.setZero();
  system.prescribed_loads.setZero();
}

void ScatterPlan::scatter(Index block, const MatrixX& local_matrix,
                          const VectorX& prescribed_values, LinearSystem& system) const {
  const Index* dofs = blocks_.dofs.data() + blocks_.offsets[block];
  const int n = blocks_.block_size(block);
  FF_ASSERT(local_matrix.rows() == n && local_matrix.cols() == n, "local matrix size");
  Real* values = system.matrix.valuePtr();
  const Index* slot = slots_.data() + slot_offsets_[block];
  for (int a = 0; a < n; ++a) {
    const Index row = free_index_[dofs[a]];
    for (int b = a; b < n; ++b, ++slot)
      if (*slot >= 0) values[*slot] += local_matrix(a, b);
    if (row < 0) continue;
    // Move the prescribed columns to the right-hand side: F_f −= K_fc u_c (most
    // blocks have none: the list is precomputed, not searched per row).
    for (Index k = prescribed_local_offsets_[block]; k < prescribed_local_offsets_[block + 1];
         ++k) {
      const int b = prescribed_local_[k];
      system.rhs[row] -= local_matrix(a, b) * prescribed_values[dofs[b]];
    }
  }
  Real* reaction_values = system.reaction_rows.valuePtr();
  for (Index k = reaction_offsets_[block]; k < reaction_offsets_[block + 1]; ++k) {
    const ReactionSlot& entry = reaction_slots_[k];
    reaction_values[entry.slot] += local_matrix(entry.local_row, entry.local_column);
  }
}

VectorX ScatterPlan::expand(const VectorX& free_values, const VectorX& prescribed_values) const {
  VectorX full = prescribed_values;
  for (Index dof = 0; dof < n_dofs(); ++dof)
    if (free_index_[dof] >= 0) full[dof] = free_values[free_index_[dof]];
  return full;
}

} // namespace formflow::assembly
