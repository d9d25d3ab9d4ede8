// SPDX-License-Identifier: MIT
#include "formflow/mesh/cell_graph.hpp"

#include <algorithm>

namespace formflow::mesh {

template <int dim> CellGraph cell_graph(const Mesh<dim>& mesh) {
  const Index n_cells = mesh.n_cells();
  const Index n_nodes = mesh.n_nodes();
  // The cells of every node (compressed by a counting pass).
  std::vector<Index> node_start(static_cast<std::size_t>(n_nodes) + 1, 0);
  for (Index cell = 0; cell < n_cells; ++cell)
    for (Index a = 0; a < mesh.cells.rows(); ++a) ++node_start[mesh.cells(a, cell) + 1];
  for (Index node = 0; node < n_nodes; ++node) node_start[node + 1] += node_start[node];
  std::vector<Index> next(node_start.begin(), node_start.end() - 1);
  std::vector<Index> node_cells(static_cast<std::size_t>(node_start.back()));
  for (Index cell = 0; cell < n_cells; ++cell)
    for (Index a = 0; a < mesh.cells.rows(); ++a) node_cells[next[mesh.cells(a, cell)]++] = cell;

  CellGraph graph;
  graph.offsets.reserve(static_cast<std::size_t>(n_cells) + 1);
  std::vector<Index> seen(static_cast<std::size_t>(n_cells), -1), row;
  for (Index cell = 0; cell < n_cells; ++cell) {
    row.clear();
    seen[cell] = cell;
    for (Index a = 0; a < mesh.cells.rows(); ++a) {
      const Index node = mesh.cells(a, cell);
      for (Index k = node_start[node]; k < node_start[node + 1]; ++k)
        if (const Index other = node_cells[k]; seen[other] != cell) {
          seen[other] = cell;
          row.push_back(other);
        }
    }
    std::sort(row.begin(), row.end());
    graph.neighbours.insert(graph.neighbours.end(), row.begin(), row.end());
    graph.offsets.push_back(static_cast<Index>(graph.neighbours.size()));
  }
  return graph;
}

template CellGraph cell_graph<2>(const Mesh<2>&);
template CellGraph cell_graph<3>(const Mesh<3>&);

} // namespace formflow::mesh
