// SPDX-License-Identifier: MIT
// A lattice of cubes with the exit's outside removed: the square die in 3D.
#include "formflow/mesh/rectangle_channel_mesh.hpp"

#include "formflow/core/error.hpp"

#include <array>
#include <vector>

namespace formflow::mesh {

namespace {

/// Lattice coordinates along one axis through breakpoints b_0 = 0 < b_1 < …, each
/// piece cut into cells of `size`: the breakpoints are exact lattice values, so
/// the die plane and the exit's sides never move by rounding.
struct Axis {
  std::vector<Real> lattice; // order·n_cells + 1 values
  int n_cells = 0;
};

Axis make_axis(const std::vector<Real>& breakpoints, Real size, int order) {
  Axis axis;
  axis.lattice.push_back(breakpoints.front());
  for (std::size_t piece = 0; piece + 1 < breakpoints.size(); ++piece) {
    const Real from = breakpoints[piece], to = breakpoints[piece + 1];
    if (to == from) continue; // an exit as wide as the container: no step in z
    const int cells = cells_along(to - from, size);
    FF_ASSERT(cells > 0, "mesh.size fits every piece (case validation)");
    const int steps = cells * order;
    for (int k = 1; k <= steps; ++k)
      axis.lattice.push_back(k == steps ? to : from + (to - from) * k / steps);
    axis.n_cells += cells;
  }
  return axis;
}

/// Centre of cell `c` along `axis` (between its first and last lattice value).
Real centre(const Axis& axis, int c, int order) {
  return 0.5 * (axis.lattice[c * order] + axis.lattice[(c + 1) * order]);
}

} // namespace

Mesh<3> make_rectangle_channel_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                    Real size, int order) {
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  const Real die_x = geometry.container_length;
  const Real land_end = die_x + geometry.land_length;
  std::vector<Real> x_breaks = {0.0, die_x};
  if (geometry.land_length > 0) x_breaks.push_back(land_end);
  x_breaks.push_back(die_x + geometry.exit_length);
  const std::array<Axis, 3> axes = {
      make_axis(x_breaks, size, order),
      make_axis({0.0, geometry.exit_half_height, geometry.entry_half_height}, size, order),
      make_axis({0.0, solid.exit_half_width, solid.entry_half_width}, size, order)};
  const std::array<int, 3> n_cells = {axes[0].n_cells, axes[1].n_cells, axes[2].n_cells};
  const auto cell_exists = [&](const std::array<int, 3>& c) {
    for (int axis = 0; axis < 3; ++axis)
      if (c[axis] < 0 || c[axis] >= n_cells[axis]) return false;
    return centre(axes[0], c[0], order) < die_x ||
           (centre(axes[1], c[1], order) < geometry.exit_half_height &&
            centre(axes[2], c[2], order) < solid.exit_half_width);
  };

  // Lattice nodes used by an existing cell, numbered x fastest.
  const std::array<int, 3> n_lattice = {n_cells[0] * order + 1, n_cells[1] * order + 1,
                                        n_cells[2] * order + 1};
  const auto lattice_index = [&](int i, int j, int k) {
    return (Index(k) * n_lattice[1] + j) * n_lattice[0] + i;
  };
  std::vector<Index> node_of(static_cast<std::size_t>(n_lattice[0]) * n_lattice[1] * n_lattice[2],
                             -1);
  std::vector<std::array<int, 3>> cells;
  for (int k = 0; k < n_cells[2]; ++k)
    for (int j = 0; j < n_cells[1]; ++j)
      for (int i = 0; i < n_cells[0]; ++i)
        if (cell_exists({i, j, k})) cells.push_back({i, j, k});
  const int n_side = order + 1;
  Index n_nodes = 0;
  for (const auto& c : cells)
    for (int cz = 0; cz < n_side; ++cz)
      for (int cy = 0; cy < n_side; ++cy)
        for (int cx = 0; cx < n_side; ++cx) {
          Index& node =
              node_of[lattice_index(c[0] * order + cx, c[1] * order + cy, c[2] * order + cz)];
          if (node < 0) node = n_nodes++;
        }

  Mesh<3> mesh;
  mesh.order = order;
  mesh.nodes.resize(3, n_nodes);
  for (int k = 0; k < n_lattice[2]; ++k)
    for (int j = 0; j < n_lattice[1]; ++j)
      for (int i = 0; i < n_lattice[0]; ++i)
        if (const Index node = node_of[lattice_index(i, j, k)]; node >= 0)
          mesh.nodes.col(node) << axes[0].lattice[i], axes[1].lattice[j], axes[2].lattice[k];
  mesh.cells.resize(n_side * n_side * n_side, static_cast<Index>(cells.size()));
  for (std::size_t cell = 0; cell < cells.size(); ++cell) {
    const auto& c = cells[cell];
    for (int cz = 0; cz < n_side; ++cz)
      for (int cy = 0; cy < n_side; ++cy)
        for (int cx = 0; cx < n_side; ++cx)
          mesh.cells((cz * n_side + cy) * n_side + cx, cell) =
              node_of[lattice_index(c[0] * order + cx, c[1] * order + cy, c[2] * order + cz)];
    // A face is on the boundary where the neighbour across it does not exist.
    const Real x_centre = centre(axes[0], c[0], order);
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2, side = face % 2;
      std::array<int, 3> neighbour = c;
      neighbour[axis] += side == 0 ? -1 : 1;
      if (cell_exists(neighbour)) continue;
      BoundaryLabel label = BoundaryLabel::FreeExit;
      if (axis == 0)
        label = side == 0                ? BoundaryLabel::Rear
                : c[0] + 1 == n_cells[0] ? BoundaryLabel::Front
                                         : BoundaryLabel::Die; // the plane x = L_c
      else if (side == 0)
        label = BoundaryLabel::Symmetry;
      else if (x_centre < die_x)
        label = BoundaryLabel::Container;
      else if (x_centre < land_end)
        label = BoundaryLabel::Die;
      mesh.facets.push_back({static_cast<Index>(cell), face, label});
    }
  }
  return mesh;
}

} // namespace formflow::mesh
