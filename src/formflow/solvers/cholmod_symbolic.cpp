// SPDX-License-Identifier: MIT
// The CHOLMOD back-end's order and supernodal symbolic factor.
#include "formflow/solvers/cholmod_symbolic.hpp"

namespace formflow::solvers {

cholmod_sparse cholmod_lower_view(const assembly::SparseMatrix& matrix) {
  cholmod_sparse view{};
  view.nrow = static_cast<std::size_t>(matrix.rows());
  view.ncol = static_cast<std::size_t>(matrix.cols());
  view.nzmax = static_cast<std::size_t>(matrix.nonZeros());
  view.p = const_cast<Index*>(matrix.outerIndexPtr());
  view.i = const_cast<Index*>(matrix.innerIndexPtr());
  view.x = const_cast<Real*>(matrix.valuePtr());
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

cholmod_factor* analyse_supernodal(const assembly::SparseMatrix& lower, cholmod_common& common,
                                   std::vector<Index>& order, PermutedLower& permuted) {
  // 1. The order: CHOLMOD's default strategy on A (no supernodal symbolic needed).
  cholmod_sparse view = cholmod_lower_view(lower);
  common.nmethods = 0;
  common.postorder = 1;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_factor* ordering = cholmod_analyze(&view, &common);
  const bool ordered = ordering && common.status == CHOLMOD_OK;
  if (ordered) {
    const Index* perm = static_cast<const Index*>(ordering->Perm);
    order.assign(perm, perm + ordering->n);
    permuted = PermutedLower(lower, order);
  }
  cholmod_free_factor(&ordering, &common);
  if (!ordered) return nullptr;
  // 2. The supernodal symbolic factor of P A Pᵀ in its natural order.
  cholmod_sparse permuted_view = cholmod_lower_view(permuted.matrix());
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_NATURAL;
  common.postorder = 0;
  common.supernodal = CHOLMOD_SUPERNODAL;
  cholmod_factor* factor = cholmod_analyze(&permuted_view, &common);
  if (factor && common.status != CHOLMOD_OK) cholmod_free_factor(&factor, &common);
  return factor;
}

} // namespace formflow::solvers
