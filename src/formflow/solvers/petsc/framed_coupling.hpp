// SPDX-License-Identifier: MIT
// The coupling block of a saddle point in the unknowns PETSc solves for (issue 20), for
// the sequential and the distributed four-block nests alike.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/petsc/node_block_layout.hpp"

#include <Eigen/SparseCore>

#include <vector>

namespace formflow::solvers::petsc {

/// The entries of P Qᵀ Bᵀ: `coupling` B (n_p × n_v), `frames` Q (n_v square, or empty for
/// none) and `layout` P of the velocity block (or empty). One triplet (solved velocity
/// row, pressure column, value) per entry, column by column; their transposes are B's
/// block, B Q Pᵀ.
std::vector<Eigen::Triplet<Real, Index>> framed_coupling(const assembly::SparseMatrix& coupling,
                                                         const assembly::SparseMatrix& frames,
                                                         const NodeBlockLayout& layout);

} // namespace formflow::solvers::petsc
