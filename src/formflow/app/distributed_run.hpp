// SPDX-License-Identifier: MIT
// A run on several MPI ranks (issue 20, docs/petsc.md): the rank and the reduction,
// set once by main, and what such a run serves yet.
#pragma once

#include "formflow/assembly/distribution.hpp"
#include "formflow/io/case.hpp"

namespace formflow::app {

/// Set by main (app/main.cpp) when the launcher started more than one rank.
void set_distribution(assembly::Distribution distribution);
/// This process's place: rank 0 of 1 unless main said otherwise.
const assembly::Distribution& distribution();
/// Only rank 0 writes results and prints.
inline bool is_output_rank() {
  return distribution().rank == 0;
}

/// The iteration callback's safe point: throws Stopped after SIGINT/SIGTERM
/// (app/stop_signals.hpp). On several ranks they agree first (a sum over the ranks of
/// the signals seen), so that all stop at the same iteration: a rank that stopped alone
/// would leave the others waiting in the next factorisation.
void stop_if_signalled();

/// On more than one rank, refuses (InputError naming the key, before the solve) what the
/// distributed slice does not serve: a linear solver other than PETSc, any loop but
/// secant and Newton (penalty or condensed mixed with d > 0; regularised or exact
/// friction, without exact stick), hot forming, the load's error estimate, the
/// manufactured solutions.
void check_distributed(const io::Case& case_);

/// `case_` loaded from `path` with `overrides`, and on more than one rank with PETSc as
/// the default of solver.linear (the one distributed back-end: `mpirun -np 2 formflow
/// run case.toml` runs): a case that sets solver.linear keeps its choice (and
/// check_distributed refuses any but PETSc, naming the key). Likewise friction.stick:
/// left unset where it would resolve to exact stick (serial only), it is "augmented".
io::Case load_run_case(const std::string& path, std::vector<io::Override> overrides);

} // namespace formflow::app
