// SPDX-License-Identifier: MIT
// A distributed run as the assembly sees it (issue 20, docs/petsc.md): which rank
// this is, how many there are, and how to sum numbers over them. The assembly layer
// knows no MPI; the app hands it the sum (solvers/petsc/petsc_session.hpp).
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/mesh/cell_partition.hpp"

#include <functional>
#include <memory>
#include <span>

namespace formflow::assembly {

/// The ranks' shares of a ghosted vector added up (a distributed run's Newton force and
/// Jacobian products, assembly::OwnedDofs::sum_shares): `held` is this rank's owned
/// entries, then its ghosts', in the order the exchange was made with; afterwards each
/// owned entry is the sum of every rank's share of it and each ghost its owner's sum.
/// Collective; the traffic is the partition's interface, not the whole vector.
class GhostExchange {
public:
  virtual ~GhostExchange() = default;
  virtual void sum_shares(std::span<Real> held) = 0;
};

/// Makes the exchange of a rank that owns `n_owned` dofs (numbered consecutively from
/// its first, ranks in order) and holds ghosts of the global numbers `ghost_globals`.
using GhostExchangeFactory = std::function<std::unique_ptr<GhostExchange>(
    Index n_owned, std::span<const Index> ghost_globals)>;

struct Distribution {
  int rank = 0;
  int size = 1;
  /// Replaces every entry by its sum over the ranks; collective, and the result is the
  /// same bits on every rank (their decisions are taken from it).
  std::function<void(std::span<Real>)> sum_over_ranks;
  /// How the cells are split among the ranks (PT-Scotch through PETSc, set by main);
  /// without one, slabs along x (mesh::cell_partition).
  mesh::GraphPartitioner partition_cells = {};
  /// The ghost exchange (PETSc's ghosted vectors, set by main); without one (a test that
  /// plays the ranks in one process), shares are added up by sum_over_ranks, whole.
  GhostExchangeFactory make_ghost_exchange = {};
  bool distributed() const { return size > 1; }
};

} // namespace formflow::assembly
