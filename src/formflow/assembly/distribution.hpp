// SPDX-License-Identifier: MIT
// A distributed run as the assembly sees it (issue 20, docs/petsc.md): which rank
// this is, how many there are, and how to sum numbers over them. The assembly layer
// knows no MPI; the app hands it the sum (solvers/petsc/petsc_session.hpp).
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/mesh/cell_partition.hpp"

#include <functional>
#include <span>

namespace formflow::assembly {

struct Distribution {
  int rank = 0;
  int size = 1;
  /// Replaces every entry by its sum over the ranks; collective, and the result is the
  /// same bits on every rank (their decisions are taken from it).
  std::function<void(std::span<Real>)> sum_over_ranks;
  /// How the cells are split among the ranks (PT-Scotch through PETSc, set by main);
  /// without one, slabs along x (mesh::cell_partition).
  mesh::GraphPartitioner partition_cells = {};
  bool distributed() const { return size > 1; }
};

} // namespace formflow::assembly
