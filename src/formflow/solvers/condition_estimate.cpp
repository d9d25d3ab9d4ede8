// SPDX-License-Identifier: MIT
// rcond through CHOLMOD's own factorisation (Eigen's wrapper hides its factor).
#include "formflow/solvers/condition_estimate.hpp"

#include <Eigen/CholmodSupport>

namespace formflow::solvers {

Real reciprocal_condition_estimate(const assembly::SparseMatrix& lower) {
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  // A simplicial LLᵀ keeps the diagonal of L directly readable by cholmod_rcond.
  common.supernodal = CHOLMOD_SIMPLICIAL;
  common.final_ll = 1;
  assembly::SparseMatrix copy = lower; // viewAsCholmod needs a non-const matrix
  cholmod_sparse view = Eigen::viewAsCholmod(Eigen::Ref<assembly::SparseMatrix>(copy));
  view.stype = -1; // symmetric, lower triangle stored
  cholmod_factor* factor = cholmod_analyze(&view, &common);
  Real rcond = 0.0;
  if (factor && cholmod_factorize(&view, factor, &common) && common.status == CHOLMOD_OK)
    rcond = cholmod_rcond(factor, &common);
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
  return rcond;
}

} // namespace formflow::solvers
