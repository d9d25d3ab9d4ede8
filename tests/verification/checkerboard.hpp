// SPDX-License-Identifier: MIT
// How much of a cell-pressure field is the 2×2 checkerboard (Remark 4.3).
#pragma once

#include "support/inf_sup.hpp"

namespace formflow::testing {

/// ‖p − filter(p)‖ / ‖p‖ over the cells with centre x < x_max (the container):
/// 0 for a field without checkerboard, O(h²) for the cell means of a smooth one.
inline double checkerboard_share(const mesh::Mesh<2>& mesh, Real size, const VectorX& cell_pressure,
                                 Real x_max) {
  const VectorX filtered = testing::filter_checkerboard(mesh, size, cell_pressure);
  double removed = 0.0, total = 0.0;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Real centre = 0.0;
    for (int a = 0; a < mesh.nodes_per_cell(); ++a) centre += mesh.nodes(0, mesh.cells(a, cell));
    if (centre / mesh.nodes_per_cell() >= x_max) continue;
    removed += (cell_pressure[cell] - filtered[cell]) * (cell_pressure[cell] - filtered[cell]);
    total += cell_pressure[cell] * cell_pressure[cell];
  }
  return total > 0 ? std::sqrt(removed / total) : 0.0;
}

} // namespace formflow::testing
