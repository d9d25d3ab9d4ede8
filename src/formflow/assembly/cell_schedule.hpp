// SPDX-License-Identifier: MIT
// The cells of an assembly loop in phases of blocks that share no node.
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <span>
#include <vector>

namespace formflow::assembly {

/// An order of a loop's cells in which blocks can be assembled at the same time. The
/// loop runs phase after phase; within a phase no two blocks share a node, hence no dof,
/// so their scatters, loads and forces write to different entries and the blocks may run
/// on different threads. A block's cells keep the loop's order.
///
/// Every entry of a matrix or vector then receives its cells' contributions in the same
/// order however many threads run the blocks (the phases in order; in each, the one
/// block that touches the entry, cell by cell): results are bit for bit those of one
/// thread. The blocks depend on the mesh only, never on the machine, for that reason.
struct CellSchedule {
  std::vector<std::vector<std::vector<Index>>> phases; ///< phases[p][b]: block b's cells
  /// The cells of all phases, for a check (each loop cell once).
  std::size_t n_cells() const;
};

/// The schedule of `cells` (the loop's order) of `mesh`: the cells cut into `n_blocks`
/// parts of about equal size by recursive coordinate bisection of their centroids (each
/// cut at the median across the longest side of the part's box: compact parts, short
/// boundaries); the cells with a node in two parts are taken out into the next phase,
/// cut the same way, until few are left, which form the last phase's one block.
template <int dim>
CellSchedule make_cell_schedule(const mesh::Mesh<dim>& mesh, std::span<const Index> cells,
                                int n_blocks);

} // namespace formflow::assembly
