// SPDX-License-Identifier: MIT
// The CHOLMOD back-end's analysis: its fill-reducing order, then the supernodal symbolic
// factor of the permuted matrix in its natural order.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/permuted_lower.hpp"

#include <cholmod.h>

#include <vector>

namespace formflow::solvers {

/// A view of `matrix` as CHOLMOD's symmetric matrix stored by its lower triangle
/// (CHOLMOD reads it only; the non-const pointers are its C interface's).
cholmod_sparse cholmod_lower_view(const assembly::SparseMatrix& matrix);

/// The supernodal symbolic factor of P A Pᵀ, A = `lower` (compressed): P is CHOLMOD's
/// default fill-reducing order (AMD, METIS where AMD fills much; then a weighted
/// postorder), written to `order` (new row k is A's row order[k]); tril(P A Pᵀ) is formed
/// into `permuted` (solvers/permuted_lower.hpp) and analysed in its natural order, so that
/// CHOLMOD factorises it as it is, without permuting at every factorisation. Allocated with
/// `common`, whose nnz(tril(A)), nnz(L) and flops it leaves set; null if CHOLMOD failed.
cholmod_factor* analyse_supernodal(const assembly::SparseMatrix& lower, cholmod_common& common,
                                   std::vector<Index>& order, PermutedLower& permuted);

} // namespace formflow::solvers
