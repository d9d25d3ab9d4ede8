// SPDX-License-Identifier: MIT
// tril(P A Pᵀ): the pattern and source slots once, the values by a gather.
#include "formflow/solvers/permuted_lower.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <numeric>

namespace formflow::solvers {

PermutedLower::PermutedLower(const assembly::SparseMatrix& lower, std::span<const Index> order) {
  FF_ASSERT(lower.isCompressed(), "a compressed lower triangle");
  const Index n = static_cast<Index>(lower.cols());
  FF_ASSERT(static_cast<Index>(order.size()) == n && lower.rows() == n, "one order entry per row");
  std::vector<Index> position(n, -1); // A's row → its row in P A Pᵀ
  for (Index k = 0; k < n; ++k) position[order[k]] = k;
  const Index* starts = lower.outerIndexPtr();
  const Index* rows = lower.innerIndexPtr();
  // Entry (i, j) of A's lower triangle goes to (max, min) of its new indices (an entry
  // above the diagonal is not A's: skipped). Two counting passes put the rows of each
  // new column in ascending order: the entries ordered by new row first, then
  // distributed to their columns in that order.
  source_nonzeros_ = static_cast<Index>(lower.nonZeros());
  std::vector<Index> new_row(source_nonzeros_, -1), new_column(source_nonzeros_, -1);
  std::vector<Index> row_starts(static_cast<std::size_t>(n) + 1, 0);
  std::vector<Index> column_starts(static_cast<std::size_t>(n) + 1, 0);
  for (Index j = 0; j < n; ++j)
    for (Index slot = starts[j]; slot < starts[j + 1]; ++slot) {
      if (rows[slot] < j) continue;
      const Index a = position[rows[slot]], b = position[j];
      new_row[slot] = std::max(a, b);
      new_column[slot] = std::min(a, b);
      ++row_starts[new_row[slot] + 1];
      ++column_starts[new_column[slot] + 1];
    }
  std::partial_sum(row_starts.begin(), row_starts.end(), row_starts.begin());
  std::partial_sum(column_starts.begin(), column_starts.end(), column_starts.begin());
  const Index nnz = column_starts[n];
  std::vector<Index> by_row(nnz); // A's lower slots in ascending new row
  for (Index slot = 0; slot < source_nonzeros_; ++slot)
    if (new_row[slot] >= 0) by_row[row_starts[new_row[slot]]++] = slot;
  permuted_.resize(n, n);
  permuted_.resizeNonZeros(nnz);
  std::copy(column_starts.begin(), column_starts.end(), permuted_.outerIndexPtr());
  source_.resize(nnz);
  Index* permuted_rows = permuted_.innerIndexPtr();
  for (const Index slot : by_row) {
    const Index e = column_starts[new_column[slot]]++;
    permuted_rows[e] = new_row[slot];
    source_[e] = slot;
  }
  refill(lower);
}

void PermutedLower::refill(const assembly::SparseMatrix& lower) {
  FF_ASSERT(lower.nonZeros() == source_nonzeros_, "the pattern the permuted copy was built for");
  const Real* values = lower.valuePtr();
  Real* target = permuted_.valuePtr();
  const Index nnz = static_cast<Index>(source_.size());
  for (Index e = 0; e < nnz; ++e) target[e] = values[source_[e]];
}

} // namespace formflow::solvers
