// SPDX-License-Identifier: MIT
// The lower triangle of P A Pᵀ, built once per pattern and refilled by a gather.
#pragma once

#include "formflow/assembly/sparsity.hpp"

#include <span>
#include <vector>

namespace formflow::solvers {

/// tril(P A Pᵀ) of a symmetric A given by its lower triangle, for a permutation fixed
/// with the pattern: (P A Pᵀ)(k, l) = A(order[k], order[l]). The pattern (compressed
/// columns, sorted rows) and the source slot of every entry are computed once; refill()
/// then copies A's values into place, one gather of nnz entries.
///
/// Why: CHOLMOD factorises P A Pᵀ. Given A and its fill-reducing order it forms that
/// matrix itself at every factorisation, by two permuted transposes of A (a lower
/// triangle is turned into the upper one and back). Those transposes were a quarter of
/// each factorisation's time on 2D Q2 meshes (docs/benchmarks.md "CHOLMOD's permuted
/// copy"). Given tril(P A Pᵀ) with the natural order instead, CHOLMOD factorises the
/// matrix as it is.
class PermutedLower {
public:
  PermutedLower() = default;
  /// The pattern of tril(P A Pᵀ) for A's lower triangle `lower` (compressed) and
  /// `order` (new row k is A's row order[k]; a permutation of 0 … n−1). Entries of
  /// `lower` above the diagonal are not read.
  PermutedLower(const assembly::SparseMatrix& lower, std::span<const Index> order);

  /// Copies the values of `lower` (the pattern given to the constructor) into matrix().
  void refill(const assembly::SparseMatrix& lower);
  /// Whether `lower` has as many entries as the pattern given to the constructor.
  bool fits(const assembly::SparseMatrix& lower) const {
    return lower.isCompressed() && lower.nonZeros() == source_nonzeros_;
  }
  /// tril(P A Pᵀ): compressed columns, rows sorted within each column.
  const assembly::SparseMatrix& matrix() const { return permuted_; }
  assembly::SparseMatrix& matrix() { return permuted_; }

private:
  assembly::SparseMatrix permuted_;
  std::vector<Index> source_; ///< A's value slot of each entry of permuted_
  Index source_nonzeros_ = 0; ///< entries of the pattern given (both triangles)
};

} // namespace formflow::solvers
