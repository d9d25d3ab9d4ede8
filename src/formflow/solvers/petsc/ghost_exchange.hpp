// SPDX-License-Identifier: MIT
// The ranks' shares of a ghosted vector added up through PETSc's ghosted vectors
// (issue 20, docs/petsc.md "Distributed runs"): assembly::GhostExchange for main to
// hand the assembly, which knows no MPI.
#pragma once

#include "formflow/assembly/distribution.hpp"

#include <memory>
#include <span>

namespace formflow::solvers::petsc {

/// A VecCreateGhost vector of `n_owned` owned entries and the ghosts `ghost_globals`:
/// sum_shares adds the ghosts' values into their owners (SCATTER_REVERSE, ADD_VALUES)
/// and sends the owners' sums back to every ghost (SCATTER_FORWARD, INSERT_VALUES), so
/// every rank that holds a dof gets the owner's bits. Collective (made and used by every
/// rank alike).
std::unique_ptr<assembly::GhostExchange> make_ghost_exchange(Index n_owned,
                                                             std::span<const Index> ghost_globals);

} // namespace formflow::solvers::petsc
