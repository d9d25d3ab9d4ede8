// SPDX-License-Identifier: MIT
// Orthonormal changes of basis of a few unknowns each (the Γ3 nodes' velocity dofs
// turned into their normal–tangent frame), which a linear back-end may solve in.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/core/types.hpp"

#include <span>
#include <vector>

namespace formflow::assembly {

/// One orthogonal change of basis: the unknowns x[rows[i]] of a system are
/// x[rows[i]] = Σ_j basis(i, j) y_j, where y are the unknowns in the frame. `basis` is
/// square (rows.size() × rows.size()) and orthonormal, so y_j = Σ_i basis(i, j) x[rows[i]]
/// and K x = b becomes (Qᵀ K Q) y = Qᵀ b with the same solution and conditioning.
struct LocalFrame {
  std::vector<Index> rows;
  MatrixX basis;
};

/// In place: x ← Qᵀ x (the frames' coordinates of a vector over rows ≥ every frame row).
void to_frames(std::span<const LocalFrame> frames, VectorX& x);

/// In place: y ← Q y (back from the frames' coordinates); the inverse of to_frames.
void from_frames(std::span<const LocalFrame> frames, VectorX& y);

/// The n × n matrix Q: the frames' bases on their rows and columns, identity elsewhere.
SparseMatrix frame_matrix(std::span<const LocalFrame> frames, Index n);

} // namespace formflow::assembly
