// SPDX-License-Identifier: MIT
// The cells' adjacency (issue 20): what a graph partitioner splits among MPI ranks.
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <vector>

namespace formflow::mesh {

/// Cell c's neighbours are neighbours[offsets[c] .. offsets[c + 1]), ascending, without c:
/// the cells that share at least one node with it. A rank's matrix rows couple to every
/// cell around their nodes, so the cut of this graph is what the ranks exchange (a
/// facet-only graph would miss the couplings across edges and corners).
struct CellGraph {
  std::vector<Index> offsets{0};
  std::vector<Index> neighbours;
  Index n_cells() const { return static_cast<Index>(offsets.size()) - 1; }
};

template <int dim> CellGraph cell_graph(const Mesh<dim>& mesh);

} // namespace formflow::mesh
