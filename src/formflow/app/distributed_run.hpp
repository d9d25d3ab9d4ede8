// SPDX-License-Identifier: MIT
// A run on several MPI ranks (issue 20, docs/petsc.md): the rank and the reduction,
// set once by main (what such a run serves yet: solvers/stage_table.hpp).
#pragma once

#include "formflow/assembly/distribution.hpp"

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

} // namespace formflow::app
