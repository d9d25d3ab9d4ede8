// SPDX-License-Identifier: MIT
// Structured generator of the two-block extrusion channel.
#include "formflow/mesh/channel_mesh.hpp"

#include "formflow/core/error.hpp"

#include <cmath>
#include <vector>

namespace formflow::mesh {

int cells_along(Real length, Real size) {
  if (!(size > 0) || !(length > 0)) return -1;
  const Real ratio = length / size;
  // Beyond a million cells along one length the mesh could not be stored
  // anyway; refusing here also keeps the int conversion defined.
  if (!(ratio <= 1e6)) return -1;
  const Real rounded = std::round(ratio);
  if (rounded < 1 || std::abs(ratio - rounded) > 1e-9 * std::max<Real>(1.0, ratio)) return -1;
  return static_cast<int>(rounded);
}

Mesh<2> make_channel_mesh(const ChannelGeometry& geometry, Real size, int order) {
  const int n_container_x = cells_along(geometry.container_length, size);
  const int n_exit_x = cells_along(geometry.exit_length, size);
  const int n_entry_y = cells_along(geometry.entry_half_height, size);
  const int n_exit_y = cells_along(geometry.exit_half_height, size);
  FF_ASSERT(n_container_x > 0 && n_exit_x > 0 && n_entry_y > 0 && n_exit_y > 0,
            "mesh size must fit the geometry");
  FF_ASSERT(n_exit_y < n_entry_y, "the exit must be thinner than the container");
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");

  // Node lattice with spacing size/order; lattice point (i, j) exists in the
  // container (i ≤ I_c) for j ≤ J_in and in the exit for j ≤ J_out.
  const int lattice_container_x = n_container_x * order;
  const int lattice_total_x = (n_container_x + n_exit_x) * order;
  const int lattice_entry_y = n_entry_y * order;
  const int lattice_exit_y = n_exit_y * order;

  Mesh<2> mesh;
  mesh.order = order;
  std::vector<Index> lattice_node((lattice_total_x + 1) * (lattice_entry_y + 1), -1);
  auto lattice_index = [&](int i, int j) { return j * (lattice_total_x + 1) + i; };
  std::vector<Point<2>> points;
  for (int j = 0; j <= lattice_entry_y; ++j)
    for (int i = 0; i <= lattice_total_x; ++i)
      if (i <= lattice_container_x || j <= lattice_exit_y) {
        lattice_node[lattice_index(i, j)] = static_cast<Index>(points.size());
        // The last lattice line is placed on the exact end coordinate so that
        // rounding in `spacing` never moves a boundary.
        const Real x =
            i <= lattice_container_x
                ? geometry.container_length * i / lattice_container_x
                : geometry.container_length + geometry.exit_length * (i - lattice_container_x) /
                                                  (lattice_total_x - lattice_container_x);
        const Real y = j <= lattice_exit_y
                           ? geometry.exit_half_height * j / lattice_exit_y
                           : geometry.exit_half_height +
                                 (geometry.entry_half_height - geometry.exit_half_height) *
                                     (j - lattice_exit_y) / (lattice_entry_y - lattice_exit_y);
        points.push_back(Point<2>(x, y));
      }
  mesh.nodes.resize(2, static_cast<Index>(points.size()));
  for (std::size_t n = 0; n < points.size(); ++n) mesh.nodes.col(static_cast<Index>(n)) = points[n];

  const int n_side = order + 1;
  std::vector<std::array<int, 2>> cell_origin; // lattice origin of each cell
  for (int cj = 0; cj < n_entry_y; ++cj)
    for (int ci = 0; ci < n_container_x + n_exit_x; ++ci)
      if (ci < n_container_x || cj < n_exit_y) cell_origin.push_back({ci * order, cj * order});
  mesh.cells.resize(n_side * n_side, static_cast<Index>(cell_origin.size()));
  for (std::size_t c = 0; c < cell_origin.size(); ++c) {
    const auto [i0, j0] = cell_origin[c];
    for (int b = 0; b < n_side; ++b)
      for (int a = 0; a < n_side; ++a) {
        const Index node = lattice_node[lattice_index(i0 + a, j0 + b)];
        FF_ASSERT(node >= 0, "cell node outside the lattice");
        mesh.cells(b * n_side + a, static_cast<Index>(c)) = node;
      }
  }

  // Boundary facets: a cell face is on the boundary when the neighbouring
  // cell across it does not exist; its label follows from where it lies.
  auto cell_exists = [&](int ci, int cj) {
    if (ci < 0 || cj < 0 || ci >= n_container_x + n_exit_x || cj >= n_entry_y) return false;
    return ci < n_container_x || cj < n_exit_y;
  };
  for (std::size_t c = 0; c < cell_origin.size(); ++c) {
    const int ci = cell_origin[c][0] / order, cj = cell_origin[c][1] / order;
    const std::array<std::array<int, 2>, 4> neighbour = {
        {{ci - 1, cj}, {ci + 1, cj}, {ci, cj - 1}, {ci, cj + 1}}};
    for (int face = 0; face < 4; ++face) {
      if (cell_exists(neighbour[face][0], neighbour[face][1])) continue;
      BoundaryLabel label{};
      switch (face) {
      case 0: label = BoundaryLabel::Rear; break;
      case 1: label = ci + 1 == n_container_x ? BoundaryLabel::Die : BoundaryLabel::Front; break;
      case 2: label = BoundaryLabel::Symmetry; break;
      default:
        label = ci < n_container_x ? BoundaryLabel::Container : BoundaryLabel::FreeExit;
        break;
      }
      mesh.facets.push_back({static_cast<Index>(c), face, label});
    }
  }
  return mesh;
}

} // namespace formflow::mesh
