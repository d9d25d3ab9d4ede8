// SPDX-License-Identifier: MIT
// A cheap estimate of how ill-conditioned an SPD system is (CHOLMOD's rcond).
#pragma once

#include "formflow/assembly/sparsity.hpp"

namespace formflow::solvers {

/// CHOLMOD's reciprocal condition estimate of the SPD matrix whose lower
/// triangle is `lower`: (min L_ii / max L_ii)² of its Cholesky factor (a
/// lower bound of 1/cond₂ up to a modest factor, cheap and good for trends).
/// 0 when the factorisation fails (not positive definite).
Real reciprocal_condition_estimate(const assembly::SparseMatrix& lower);

} // namespace formflow::solvers
