// SPDX-License-Identifier: MIT
// Which MPI rank assembles which cell (issue 20): a graph partitioner's split of the
// cells' adjacency where one is given (PT-Scotch through PETSc), otherwise a geometric
// split into slabs along x, the extrusion axis of every channel mesh.
#pragma once

#include "formflow/mesh/cell_graph.hpp"
#include "formflow/mesh/mesh.hpp"

#include <functional>
#include <string>
#include <vector>

namespace formflow::mesh {

/// The part (0 .. parts−1) of every cell: cells ordered by the x of their centroid
/// (ties by index, so every rank computes the same split), then cut into `parts`
/// runs whose sizes differ by at most one. A slab along the flow keeps the
/// interface between parts small (one cross-section per cut) for the channel meshes;
/// the fallback of cell_partition when no graph partitioner is given or its split fails.
template <int dim> std::vector<int> slab_partition(const Mesh<dim>& mesh, int parts);

/// A split of the cells among the ranks: the part (0 .. parts−1) of every cell, and
/// which method made it (a PETSc partitioner's type, or "slabs"), for the summary.
struct CellPartition {
  std::vector<int> part;
  std::string method;
};

/// A graph partitioner: the part of every vertex of `graph`, the same on every rank
/// (collective), and its method's name; `part` empty if it could not.
using GraphPartitioner = std::function<CellPartition(const CellGraph& graph, int parts)>;

/// The part of every cell: `partitioner`'s split of the cells' adjacency (cell_graph),
/// or the slabs where there is none, or where its split leaves a part without cells
/// (every rank must own rows) or is not one.
template <int dim>
CellPartition cell_partition(const Mesh<dim>& mesh, int parts, const GraphPartitioner& partitioner);

} // namespace formflow::mesh
