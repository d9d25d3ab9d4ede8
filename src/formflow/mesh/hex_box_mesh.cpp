// SPDX-License-Identifier: MIT
// Lattice of nodes and lexicographic hexahedra on a box.
#include "formflow/mesh/hex_box_mesh.hpp"

#include "formflow/core/error.hpp"

namespace formflow::mesh {

Mesh<3> make_hex_box_mesh(const Point<3>& lower, const Point<3>& upper,
                          const std::array<int, 3>& cells, int order,
                          const std::array<BoundaryLabel, 6>& face_labels) {
  FF_ASSERT(cells[0] > 0 && cells[1] > 0 && cells[2] > 0,
            "a box mesh needs at least one cell per direction");
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  FF_ASSERT((upper - lower).minCoeff() > 0, "the box must have positive size");
  // One lattice of `order` nodes per cell side; node (I, J, K) is numbered x fastest.
  const std::array<int, 3> lattice = {cells[0] * order + 1, cells[1] * order + 1,
                                      cells[2] * order + 1};
  auto node_index = [&](int i, int j, int k) -> Index {
    return (static_cast<Index>(k) * lattice[1] + j) * lattice[0] + i;
  };
  Mesh<3> mesh;
  mesh.order = order;
  mesh.nodes.resize(3, static_cast<Index>(lattice[0]) * lattice[1] * lattice[2]);
  for (int k = 0; k < lattice[2]; ++k)
    for (int j = 0; j < lattice[1]; ++j)
      for (int i = 0; i < lattice[0]; ++i) {
        const std::array<int, 3> at = {i, j, k};
        for (int axis = 0; axis < 3; ++axis)
          mesh.nodes(axis, node_index(i, j, k)) =
              lower[axis] + (upper[axis] - lower[axis]) * at[axis] / (lattice[axis] - 1);
      }

  const int n_side = order + 1;
  mesh.cells.resize(n_side * n_side * n_side, cells[0] * cells[1] * cells[2]);
  for (int ck = 0; ck < cells[2]; ++ck)
    for (int cj = 0; cj < cells[1]; ++cj)
      for (int ci = 0; ci < cells[0]; ++ci) {
        const Index cell = (static_cast<Index>(ck) * cells[1] + cj) * cells[0] + ci;
        for (int c = 0; c < n_side; ++c)
          for (int b = 0; b < n_side; ++b)
            for (int a = 0; a < n_side; ++a)
              mesh.cells((c * n_side + b) * n_side + a, cell) =
                  node_index(ci * order + a, cj * order + b, ck * order + c);
        const std::array<int, 3> at = {ci, cj, ck};
        for (int axis = 0; axis < 3; ++axis) {
          if (at[axis] == 0) mesh.facets.push_back({cell, 2 * axis, face_labels[2 * axis]});
          if (at[axis] == cells[axis] - 1)
            mesh.facets.push_back({cell, 2 * axis + 1, face_labels[2 * axis + 1]});
        }
      }
  return mesh;
}

} // namespace formflow::mesh
