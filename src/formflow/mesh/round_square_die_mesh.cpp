// SPDX-License-Identifier: MIT
// The round billet through a square die: the O-grid over the container, its
// rectangular core alone over the exit.
#include "formflow/mesh/round_square_die_mesh.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/cross_section_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace formflow::mesh {

namespace {

/// The x lattice through the breakpoints 0, L_c, (L_c + L_land), L_c + L_e, each
/// piece in cells of `size`; breakpoints are exact lattice values, so the die
/// plane is exactly x = L_c.
struct XAxis {
  std::vector<Real> lattice; // order·cells + 1 values
  int cells = 0;
  int container_cells = 0;
};

XAxis make_x_axis(const ChannelGeometry& geometry, Real size, int order) {
  const Real die_x = geometry.container_length;
  std::vector<Real> breaks = {0.0, die_x};
  if (geometry.land_length > 0) breaks.push_back(die_x + geometry.land_length);
  breaks.push_back(die_x + geometry.exit_length);
  XAxis axis;
  axis.lattice.push_back(0.0);
  for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
    const Real from = breaks[piece], to = breaks[piece + 1];
    const int cells = cells_along(to - from, size);
    FF_ASSERT(cells > 0, "mesh.size fits every x piece (case validation)");
    const int steps = cells * order;
    for (int k = 1; k <= steps; ++k)
      axis.lattice.push_back(k == steps ? to : from + (to - from) * k / steps);
    axis.cells += cells;
    if (piece == 0) axis.container_cells = cells;
  }
  return axis;
}

} // namespace

int round_square_ring_cells(const ChannelGeometry& geometry, const SolidChannel& solid, Real size) {
  const Real gap =
      geometry.entry_half_height - std::min(geometry.exit_half_height, solid.exit_half_width);
  return std::max(1, static_cast<int>(std::lround(gap / size)));
}

bool round_square_exit_fits(const ChannelGeometry& geometry, const SolidChannel& solid, Real size) {
  return std::hypot(geometry.exit_half_height, solid.exit_half_width) <=
         geometry.entry_half_height - 0.5 * size;
}

Mesh<3> make_round_square_die_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                   Real size, int order) {
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  const int cells_y = cells_along(geometry.exit_half_height, size);
  const int cells_z = cells_along(solid.exit_half_width, size);
  FF_ASSERT(cells_y > 0 && cells_z > 0, "mesh.size fits the exit's half sides (case validation)");
  const CoreRingSection section = make_core_ring_section(
      geometry.entry_half_height, geometry.exit_half_height, solid.exit_half_width, cells_y,
      cells_z, round_square_ring_cells(geometry, solid, size), order);
  const Mesh<2>& plane = section.mesh;
  const XAxis x = make_x_axis(geometry, size, order);
  const int n_side = order + 1;
  const Index n_section = plane.n_nodes(), n_section_cells = plane.n_cells();
  const Index n_core_cells = section.core_cells;

  // Section nodes used by the core, numbered in order: the exit's levels carry only those.
  std::vector<Index> core_index(n_section, -1);
  Index n_core = 0;
  for (Index s = 0; s < n_core_cells; ++s)
    for (int a = 0; a < n_side * n_side; ++a)
      if (Index& index = core_index[plane.cells(a, s)]; index < 0) index = n_core++;
  const Index die_level = Index(x.container_cells) * order;
  const Index n_levels = static_cast<Index>(x.lattice.size());
  const auto node = [&](Index level, Index s) {
    if (level <= die_level) return level * n_section + s;
    FF_ASSERT(core_index[s] >= 0, "downstream of the die only the core's nodes exist");
    return (die_level + 1) * n_section + (level - die_level - 1) * n_core + core_index[s];
  };

  Mesh<3> mesh;
  mesh.order = order;
  mesh.nodes.resize(3, (die_level + 1) * n_section + (n_levels - die_level - 1) * n_core);
  for (Index level = 0; level < n_levels; ++level)
    for (Index s = 0; s < n_section; ++s)
      if (level <= die_level || core_index[s] >= 0)
        mesh.nodes.col(node(level, s)) << x.lattice[level], plane.nodes(0, s), plane.nodes(1, s);

  const Index n_cells = Index(x.container_cells) * n_section_cells +
                        Index(x.cells - x.container_cells) * n_core_cells;
  mesh.cells.resize(n_side * n_side * n_side, n_cells);
  const auto cell_id = [&](int column, Index s) {
    return column < x.container_cells ? Index(column) * n_section_cells + s
                                      : Index(x.container_cells) * n_section_cells +
                                            Index(column - x.container_cells) * n_core_cells + s;
  };
  const Real land_end = geometry.container_length + geometry.land_length;
  for (int column = 0; column < x.cells; ++column) {
    const bool container = column < x.container_cells;
    const Index in_column = container ? n_section_cells : n_core_cells;
    for (Index s = 0; s < in_column; ++s) {
      const Index cell = cell_id(column, s);
      // Hexahedron node (a, b, c) = level column·order + a of section node (b, c):
      // axes x, then the section's two, positively oriented as the section cell.
      for (int in_section = 0; in_section < n_side * n_side; ++in_section)
        for (int a = 0; a < n_side; ++a)
          mesh.cells(in_section * n_side + a, cell) =
              node(Index(column) * order + a, plane.cells(in_section, s));
      if (column == 0) mesh.facets.push_back({cell, 0, BoundaryLabel::Rear});
      if (column + 1 == x.cells) mesh.facets.push_back({cell, 1, BoundaryLabel::Front});
      if (column + 1 == x.container_cells && s >= n_core_cells)
        mesh.facets.push_back({cell, 1, BoundaryLabel::Die}); // the flat die face x = L_c
    }
    // The section's faces 0–3 are its (y, z) sides, the hexahedron's faces 2–5.
    for (const BoundaryFacet& facet : plane.facets)
      if (container || facet.cell < n_core_cells)
        mesh.facets.push_back({cell_id(column, facet.cell), facet.local_face + 2,
                               facet.label == BoundaryLabel::Symmetry ? BoundaryLabel::Symmetry
                                                                      : BoundaryLabel::Container});
    if (container) continue;
    const Real x_centre = 0.5 * (x.lattice[column * order] + x.lattice[(column + 1) * order]);
    const BoundaryLabel side = x_centre < land_end ? BoundaryLabel::Die : BoundaryLabel::FreeExit;
    for (const BoundaryFacet& facet : section.core_sides)
      mesh.facets.push_back({cell_id(column, facet.cell), facet.local_face + 2, side});
  }
  return mesh;
}

Real round_square_die_cell_count(const ChannelGeometry& geometry, const SolidChannel& solid,
                                 Real size) {
  const Real cells_y = std::round(geometry.exit_half_height / size);
  const Real cells_z = std::round(solid.exit_half_width / size);
  const Real ring = round_square_ring_cells(geometry, solid, size);
  const Real core = cells_y * cells_z;
  return std::round(geometry.container_length / size) * (core + ring * (cells_y + cells_z)) +
         std::round(geometry.exit_length / size) * core;
}

} // namespace formflow::mesh
