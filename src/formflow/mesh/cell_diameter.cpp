// SPDX-License-Identifier: MIT
// Smallest and largest cell diameter of a mesh.
#include "formflow/mesh/cell_diameter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace formflow::mesh {

template <int dim> CellDiameterRange cell_diameter_range(const Mesh<dim>& mesh) {
  if (mesh.n_cells() == 0) return {};
  CellDiameterRange range{std::numeric_limits<Real>::infinity(), 0.0};
  const int n_nodes = mesh.nodes_per_cell();
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Real squared = 0.0;
    for (int a = 0; a < n_nodes; ++a)
      for (int b = a + 1; b < n_nodes; ++b)
        squared = std::max(
            squared, (mesh.nodes.col(mesh.cells(a, cell)) - mesh.nodes.col(mesh.cells(b, cell)))
                         .squaredNorm());
    range.smallest = std::min(range.smallest, squared);
    range.largest = std::max(range.largest, squared);
  }
  range.smallest = std::sqrt(range.smallest);
  range.largest = std::sqrt(range.largest);
  return range;
}

template CellDiameterRange cell_diameter_range<2>(const Mesh<2>&);
template CellDiameterRange cell_diameter_range<3>(const Mesh<3>&);

} // namespace formflow::mesh
