// SPDX-License-Identifier: MIT
// A linear solver that keeps its symbolic analysis while the pattern stays the same.
#pragma once

#include "formflow/solvers/linear_solver.hpp"

#include <memory>

namespace formflow::solvers {

/// `solver`, whose analyze() is done again only when the matrix's pattern differs
/// from the one last analysed (sizes, column starts and row indices compared: O(nnz),
/// far below an ordering). Hot forming's staggered loop solves the same flow problem
/// at each coupling step: one analysis serves them all, and the Krylov count of an
/// iterative back-end runs over all of them. factorize/solve/name/krylov_iterations/
/// set_fields are the wrapped solver's.
std::unique_ptr<LinearSolver> reuse_analysis(std::unique_ptr<LinearSolver> solver);

} // namespace formflow::solvers
