// SPDX-License-Identifier: MIT
// Where each value of PETSc's sequential matrix comes from in formflow's matrix, so that
// a refactorisation on the same pattern writes the values straight into PETSc's arrays
// (issue 20: the memory of the 3D saddle point, docs/benchmarks.md "Memory").
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/core/types.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"

#include <span>
#include <utility>
#include <vector>

namespace formflow::solvers::petsc {

/// A row-major (CSR) pattern.
struct CsrPattern {
  std::vector<Index> outer{0}, inner;
};

/// The pattern of P Qᵀ K Q Pᵀ (ValueMap below) from K's alone (`input`, values unused;
/// `lower_only`, `frames`, `layout` as for ValueMap): row by row, with no matrix product
/// and no values, so that the first copy of a large matrix is as lean as the later ones.
/// A slot of the layout holds its diagonal only.
CsrPattern solved_pattern(const assembly::SparseMatrix& input, bool lower_only,
                          const assembly::SparseMatrix& frames, const NodeBlockLayout& layout);

/// The pattern of a share's P Qᵀ K Q Pᵀ (solved_pattern: both triangles, in the layout's
/// rows) keeping the slot diagonal of the nodes this share touches only (a node with a
/// velocity diagonal in the share; `n_velocity`: the share's velocity rows): every rank
/// that touches a node has the diagonals of all its rows, so the lowest of them owns the
/// whole node (a block of `components` rows, as the "u" split's block size needs), and the
/// ranks' slot entries add up to a positive diagonal (a decoupled row all the same). A
/// rank that added the slots of nodes it does not touch would own them alone.
CsrPattern share_pattern(const assembly::SparseMatrix& share, bool lower_only,
                         const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
                         Index n_velocity);

/// PETSc solves P Qᵀ K Q Pᵀ y = P Qᵀ b: K is formflow's matrix (compressed column-major,
/// both triangles or, for a symmetric matrix, the lower one), Q the local frames' change
/// of basis (a few unknowns per Γ3 node, identity elsewhere) and P the node-block layout
/// (a permutation with decoupled slots, each given the diagonal `hole`). Every value of
/// that matrix is one value of K, except at the frames' rows and columns (a short sum
/// over the frame's unknowns) and in the slots (the hole value). The map records which,
/// once per pattern, so each refactorisation is one pass over the values with no
/// temporary copy of the matrix: before it, the copy built the product Qᵀ K Q, a
/// row-major copy, the layout's triplets and its matrix, all alive beside PETSc's
/// matrix and the previous step's AMG hierarchy (3D Q2–P1disc at h = 0.125: 0.5 of the
/// run's 1.26 GB peak heap).
class ValueMap {
public:
  ValueMap() = default;
  /// `input`: K's pattern (values unused). `frames`: Q (n × n, compressed), or empty for
  /// none. `layout`: P, or empty for the identity. `outer`, `inner`: the CSR pattern of
  /// PETSc's matrix (row-major, in the layout's rows), which must contain the pattern of
  /// P Qᵀ K Q Pᵀ. `n_velocity`: the velocity rows of a saddle point (the hole value is the
  /// mean |diagonal| over those of them in the pattern), or every row.
  ValueMap(const assembly::SparseMatrix& input, bool lower_only,
           const assembly::SparseMatrix& frames, const NodeBlockLayout& layout,
           std::span<const Index> outer, std::span<const Index> inner, Index n_velocity);

  bool empty() const { return source_.empty(); }
  /// PETSc's values (`output`, as many as the pattern has) from K's, which must have the
  /// pattern the map was made for (the caller checks: InputPattern).
  void fill(const assembly::SparseMatrix& input, std::span<Real> output) const;

private:
  static constexpr Index hole = -1, zero = -2; ///< source_ codes; ≤ −3: a sum, −3 − k
  std::vector<Index> source_;                  ///< per output value: K's value index or a code
  std::vector<Index> sum_start_;               ///< per sum: its first term (one past: the next)
  std::vector<std::pair<Index, Real>> terms_;  ///< (K's value index, weight)
  std::vector<Index> velocity_diagonal_;       ///< output indices of the velocity rows' diagonal
  std::vector<Index> holes_;                   ///< output indices of the layout's slots
  Index n_input_values_ = 0;
};

/// K's pattern at the last copy, to tell whether a refactorisation keeps it.
class InputPattern {
public:
  InputPattern() = default;
  explicit InputPattern(const assembly::SparseMatrix& input);
  bool matches(const assembly::SparseMatrix& input) const;

private:
  std::vector<Index> outer_, inner_;
};

} // namespace formflow::solvers::petsc
