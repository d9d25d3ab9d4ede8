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

ValueMap::ValueMap(const assembly::SparseMatrix& input, bool lower_only,
                   const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                   std::span<const Index> outer, std::span<const Index> inner, Index n_velocity) {
  FF_ASSERT(input.isCompressed() && input.rows() == input.cols(), "a compressed square matrix");
  const Index n = input.rows();
  FF_ASSERT(frames.size() == 0 || (frames.rows() == n && frames.isCompressed()),
            "the frames' Q is n × n and compressed");
  FF_ASSERT(layout.empty() || layout.n_rows() == n, "the layout is the matrix's");
  input_outer_.assign(input.outerIndexPtr(), input.outerIndexPtr() + n + 1);
  input_inner_.assign(input.innerIndexPtr(), input.innerIndexPtr() + input.nonZeros());

  const auto n_output = static_cast<Index>(outer.size()) - 1;
  std::vector<Index> system_row(static_cast<std::size_t>(n_output), -1); // −1: a slot
  for (Index i = 0; i < n; ++i) system_row[layout.empty() ? i : layout.position(i)] = i;

  // K's value index of entry (k, l), −1 outside its pattern.
  const auto value_index = [&](Index k, Index l) -> Index {
    if (lower_only && k < l) std::swap(k, l);
    const Index* begin = input_inner_.data() + input_outer_[l];
    const Index* end = input_inner_.data() + input_outer_[l + 1];
    const Index* found = std::lower_bound(begin, end, k);
    return found != end && *found == k ? static_cast<Index>(found - input_inner_.data()) : -1;
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
  n_velocity_ = n_velocity;
}

bool ValueMap::matches(const assembly::SparseMatrix& input) const {
  const auto n = static_cast<std::size_t>(input.outerSize());
  return input.isCompressed() && input_outer_.size() == n + 1 &&
         std::equal(input_outer_.begin(), input_outer_.end(), input.outerIndexPtr()) &&
         input_inner_.size() == static_cast<std::size_t>(input.nonZeros()) &&
         std::equal(input_inner_.begin(), input_inner_.end(), input.innerIndexPtr());
}

void ValueMap::fill(const assembly::SparseMatrix& input, std::span<Real> output) const {
  FF_ASSERT(output.size() == source_.size() && matches(input), "the pattern the map was made for");
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
  // The slots' diagonal: the mean |a_ii| of the velocity rows, so that they neither
  // dominate nor vanish beside the velocity's (as mean_absolute_diagonal).
  Real total = 0;
  for (const Index s : velocity_diagonal_) total += std::abs(output[static_cast<std::size_t>(s)]);
  const Real hole_value = total > 0 ? total / static_cast<Real>(n_velocity_) : 1.0;
  for (const Index s : holes_) output[static_cast<std::size_t>(s)] = hole_value;
}

} // namespace formflow::solvers::petsc
