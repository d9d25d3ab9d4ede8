// SPDX-License-Identifier: MIT
#include "formflow/mesh/cell_partition.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <numeric>

namespace formflow::mesh {

template <int dim> std::vector<int> slab_partition(const Mesh<dim>& mesh, int parts) {
  FF_ASSERT(parts >= 1, "at least one part");
  const Index n = mesh.n_cells();
  std::vector<Real> centroid_x(static_cast<std::size_t>(n), 0.0);
  for (Index cell = 0; cell < n; ++cell) {
    for (Index a = 0; a < mesh.cells.rows(); ++a)
      centroid_x[cell] += mesh.nodes(0, mesh.cells(a, cell));
    centroid_x[cell] /= static_cast<Real>(mesh.cells.rows());
  }
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](Index a, Index b) { return centroid_x[a] < centroid_x[b]; });
  std::vector<int> part(static_cast<std::size_t>(n), 0);
  for (Index k = 0; k < n; ++k)
    part[order[k]] = static_cast<int>((static_cast<long long>(k) * parts) / std::max<Index>(n, 1));
  return part;
}

template <int dim>
CellPartition cell_partition(const Mesh<dim>& mesh, int parts,
                             const GraphPartitioner& partitioner) {
  if (parts > 1 && partitioner) {
    CellPartition split = partitioner(cell_graph(mesh), parts);
    const std::vector<int>& part = split.part;
    std::vector<Index> cells_of(static_cast<std::size_t>(parts), 0);
    bool valid = static_cast<Index>(part.size()) == mesh.n_cells();
    for (std::size_t c = 0; valid && c < part.size(); ++c) {
      valid = part[c] >= 0 && part[c] < parts;
      if (valid) ++cells_of[static_cast<std::size_t>(part[c])];
    }
    if (valid && std::find(cells_of.begin(), cells_of.end(), 0) == cells_of.end()) return split;
  }
  return {slab_partition(mesh, parts), "slabs"};
}

template std::vector<int> slab_partition<2>(const Mesh<2>&, int);
template std::vector<int> slab_partition<3>(const Mesh<3>&, int);
template CellPartition cell_partition<2>(const Mesh<2>&, int, const GraphPartitioner&);
template CellPartition cell_partition<3>(const Mesh<3>&, int, const GraphPartitioner&);

} // namespace formflow::mesh
