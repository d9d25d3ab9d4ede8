// SPDX-License-Identifier: MIT
// The values of PETSc's sequential matrix from formflow's, without a temporary copy.
#include "formflow/solvers/petsc/value_map.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::solvers::petsc {

namespace {

/// The nonzeros (k, Q_ki) of column i of Q: x_k = Σ_i Q_ki y_i. Without frames, (i, 1).
void frame_column(const assembly::SparseMatrix& frames, Index i,
                  std::vector<std::pair<Index, Real>>& column) {
  column.clear();
  if (frames.size() == 0) {
    column.emplace_back(i, 1.0);
    return;
  }
  for (assembly::SparseMatrix::InnerIterator it(frames, i); it; ++it)
    column.emplace_back(it.row(), it.value());
}

} // namespace

CsrPattern solved_pattern(const assembly::SparseMatrix& input, bool lower_only,
                          const assembly::SparseMatrix& frames, const NodeBlockLayout& layout) {
  FF_ASSERT(input.isCompressed() && input.rows() == input.cols(), "a compressed square matrix");
  const Index n = input.rows();
  // K's rows (both triangles for lower storage), by a counting sort of its columns.
  std::vector<Index> row_start(static_cast<std::size_t>(n) + 1, 0);
  for (Index c = 0; c < n; ++c)
    for (Index k = input.outerIndexPtr()[c]; k < input.outerIndexPtr()[c + 1]; ++k) {
      const Index r = input.innerIndexPtr()[k];
      ++row_start[static_cast<std::size_t>(r) + 1];
      if (lower_only && r != c) ++row_start[static_cast<std::size_t>(c) + 1];
    }
  for (Index r = 0; r < n; ++r) row_start[r + 1] += row_start[r];
  std::vector<Index> next(row_start.begin(), row_start.end() - 1);
  std::vector<Index> row_columns(static_cast<std::size_t>(row_start.back()));
  for (Index c = 0; c < n; ++c)
    for (Index k = input.outerIndexPtr()[c]; k < input.outerIndexPtr()[c + 1]; ++k) {
      const Index r = input.innerIndexPtr()[k];
      row_columns[next[r]++] = c;
      if (lower_only && r != c) row_columns[next[c]++] = r;
    }
  next = {};

  const Index n_output = layout.empty() ? n : layout.n_embedded();
  std::vector<Index> system_row(static_cast<std::size_t>(n_output), -1); // −1: a slot
  for (Index i = 0; i < n; ++i) system_row[layout.empty() ? i : layout.position(i)] = i;
  const auto laid_out = [&](Index i) { return layout.empty() ? i : layout.position(i); };

  CsrPattern pattern;
  pattern.outer.reserve(static_cast<std::size_t>(n_output) + 1);
  pattern.inner.reserve(row_columns.size());
  std::vector<Index> seen(static_cast<std::size_t>(n_output), -1), row;
  std::vector<std::pair<Index, Real>> column_i, column_l;
  for (Index out = 0; out < n_output; ++out) {
    const Index i = system_row[out];
    row.clear();
    if (i < 0) {
      row.push_back(out);
    } else {
      // Row i of Qᵀ K Q: Σ_k Q_ki (row k of K) Q, over k in column i of Q, each K_kl
      // reaching the columns m of row l of Q (Q's pattern is symmetric: column l's).
      frame_column(frames, i, column_i);
      for (const auto& entry_k : column_i)
        for (Index t = row_start[entry_k.first]; t < row_start[entry_k.first + 1]; ++t) {
          frame_column(frames, row_columns[t], column_l);
          for (const auto& entry_m : column_l)
            if (const Index j = laid_out(entry_m.first); seen[j] != out) {
              seen[j] = out;
              row.push_back(j);
            }
        }
      std::sort(row.begin(), row.end());
    }
    pattern.inner.insert(pattern.inner.end(), row.begin(), row.end());
    pattern.outer.push_back(static_cast<Index>(pattern.inner.size()));
  }
  return pattern;
}

CsrPattern share_pattern(const assembly::SparseMatrix& share, bool lower_only,
                         const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                         Index n_velocity) {
  CsrPattern pattern = solved_pattern(share, lower_only, frames, layout);
  if (layout.empty()) return pattern;
  // The nodes this share touches: the frames act within a node, so a node with a
  // velocity diagonal in K has one in Qᵀ K Q.
  const int components = layout.components();
  std::vector<bool> touched(static_cast<std::size_t>(layout.n_velocity_embedded() / components),
                            false);
  for (Index column = 0; column < n_velocity; ++column)
    for (auto k = share.outerIndexPtr()[column]; k < share.outerIndexPtr()[column + 1]; ++k)
      if (share.innerIndexPtr()[k] == column) touched[layout.position(column) / components] = true;
  // solved_pattern gives every slot row its diagonal alone: drop the untouched ones.
  std::vector<bool> dropped(static_cast<std::size_t>(layout.n_embedded()), false);
  for (const Index slot : layout.holes()) dropped[slot] = !touched[slot / components];
  CsrPattern kept;
  kept.outer.reserve(pattern.outer.size());
  kept.inner.reserve(pattern.inner.size());
  for (std::size_t row = 0; row + 1 < pattern.outer.size(); ++row) {
    if (!dropped[row])
      kept.inner.insert(kept.inner.end(), pattern.inner.begin() + pattern.outer[row],
                        pattern.inner.begin() + pattern.outer[row + 1]);
    kept.outer.push_back(static_cast<Index>(kept.inner.size()));
  }
  return kept;
}

ValueMap::ValueMap(const assembly::SparseMatrix& input, bool lower_only,
                   const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                   std::span<const Index> outer, std::span<const Index> inner, Index n_velocity) {
  FF_ASSERT(input.isCompressed() && input.rows() == input.cols(), "a compressed square matrix");
  const Index n = input.rows();
  FF_ASSERT(frames.size() == 0 || (frames.rows() == n && frames.isCompressed()),
            "the frames' Q is n × n and compressed");
  FF_ASSERT(layout.empty() || layout.n_rows() == n, "the layout is the matrix's");
  n_input_values_ = static_cast<Index>(input.nonZeros());
  const Index* input_outer = input.outerIndexPtr();
  const Index* input_inner = input.innerIndexPtr();

  const auto n_output = static_cast<Index>(outer.size()) - 1;
  const Index n_laid_out = layout.empty() ? n : layout.n_embedded();
  std::vector<Index> system_row(static_cast<std::size_t>(n_laid_out), -1); // −1: a slot
  for (Index i = 0; i < n; ++i) system_row[layout.empty() ? i : layout.position(i)] = i;

  // K's value index of entry (k, l), −1 outside its pattern.
  const auto value_index = [&](Index k, Index l) -> Index {
    if (lower_only && k < l) std::swap(k, l);
    const Index* begin = input_inner + input_outer[l];
    const Index* end = input_inner + input_outer[l + 1];
    const Index* found = std::lower_bound(begin, end, k);
    return found != end && *found == k ? static_cast<Index>(found - input_inner) : -1;
  };

  source_.resize(inner.size());
  std::vector<std::pair<Index, Real>> column_i, column_j, sum;
  for (Index row = 0; row < n_output; ++row) {
    const Index i = system_row[row];
    if (i >= 0) frame_column(frames, i, column_i);
    for (Index s = outer[row]; s < outer[row + 1]; ++s) {
      const Index column = inner[s];
      if (i < 0) {
        FF_ASSERT(column == row, "a slot of the layout holds its diagonal only");
        source_[s] = hole;
        holes_.push_back(s);
        continue;
      }
      const Index j = system_row[column];
      FF_ASSERT(j >= 0, "a system row couples to system columns only");
      if (i == j && i < n_velocity) velocity_diagonal_.push_back(s);
      // (Qᵀ K Q)_ij = Σ_k Σ_l Q_ki K_kl Q_lj over the frames' unknowns of i and j.
      frame_column(frames, j, column_j);
      sum.clear();
      for (const auto& [k, q_ki] : column_i)
        for (const auto& [l, q_lj] : column_j)
          if (const Index v = value_index(k, l); v >= 0) sum.emplace_back(v, q_ki * q_lj);
      if (sum.empty()) {
        source_[s] = zero;
      } else if (sum.size() == 1 && sum.front().second == 1.0) {
        source_[s] = sum.front().first;
      } else {
        source_[s] = -3 - static_cast<Index>(sum_start_.size());
        sum_start_.push_back(static_cast<Index>(terms_.size()));
        terms_.insert(terms_.end(), sum.begin(), sum.end());
      }
    }
  }
  sum_start_.push_back(static_cast<Index>(terms_.size()));
  terms_.shrink_to_fit(); // kept for the run: not the growth's spare capacity
  sum_start_.shrink_to_fit();
}

InputPattern::InputPattern(const assembly::SparseMatrix& input)
    : outer_(input.outerIndexPtr(), input.outerIndexPtr() + input.outerSize() + 1),
      inner_(input.innerIndexPtr(), input.innerIndexPtr() + input.nonZeros()) {
  FF_ASSERT(input.isCompressed(), "a compressed matrix");
}

bool InputPattern::matches(const assembly::SparseMatrix& input) const {
  const auto n = static_cast<std::size_t>(input.outerSize());
  return input.isCompressed() && outer_.size() == n + 1 &&
         std::equal(outer_.begin(), outer_.end(), input.outerIndexPtr()) &&
         inner_.size() == static_cast<std::size_t>(input.nonZeros()) &&
         std::equal(inner_.begin(), inner_.end(), input.innerIndexPtr());
}

void ValueMap::fill(const assembly::SparseMatrix& input, std::span<Real> output) const {
  FF_ASSERT(output.size() == source_.size() && input.nonZeros() == n_input_values_,
            "the pattern the map was made for");
  const Real* values = input.valuePtr();
  for (std::size_t s = 0; s < source_.size(); ++s) {
    const Index code = source_[s];
    if (code >= 0) {
      output[s] = values[code];
    } else if (code <= -3) {
      const auto k = static_cast<std::size_t>(-3 - code);
      Real value = 0;
      for (Index t = sum_start_[k]; t < sum_start_[k + 1]; ++t)
        value += terms_[static_cast<std::size_t>(t)].second *
                 values[terms_[static_cast<std::size_t>(t)].first];
      output[s] = value;
    } else {
      output[s] = 0; // a structural zero (and the slots, set below)
    }
  }
  if (holes_.empty()) return;
  // The slots' diagonal: the mean |a_ii| of the velocity rows (those with a diagonal: a
  // rank's share has its own cells' rows only), so that they neither dominate nor vanish
  // beside the velocity's.
  Real total = 0;
  for (const Index s : velocity_diagonal_) total += std::abs(output[static_cast<std::size_t>(s)]);
  const Real hole_value =
      total > 0 ? total / static_cast<Real>(velocity_diagonal_.size()) : Real(1);
  for (const Index s : holes_) output[static_cast<std::size_t>(s)] = hole_value;
}

} // namespace formflow::solvers::petsc
