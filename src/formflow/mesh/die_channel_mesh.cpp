// SPDX-License-Identifier: MIT
// Mapped (transfinite) structured generator for channels with sloped or curved dies.
#include "formflow/mesh/die_channel_mesh.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/die_profile.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace formflow::mesh {

namespace {

/// A column of cells, [left, right] in x, with the label of its upper face.
struct Column {
  Real left, right;
  BoundaryLabel top;
};

void add_columns(std::vector<Column>& columns, Real from, Real to, int count, BoundaryLabel top) {
  for (int k = 0; k < count; ++k)
    columns.push_back({from + (to - from) * k / count,
                       k + 1 == count ? to : from + (to - from) * (k + 1) / count, top});
}

/// Cells along a derived length (a die face piece): never fewer than one, and
/// never longer than `size` so the face is resolved as finely as the rest.
int cells_covering(Real length, Real size) {
  return std::max(1, static_cast<int>(std::ceil(length / size - 1e-9)));
}

Mesh<2> make_mapped_mesh(const ChannelGeometry& geometry, Real size, int order) {
  const DieProfile profile(geometry);
  const Real die_entry = geometry.container_length;
  const Real die_exit = die_entry + profile.length();
  const Real land_end = die_exit + geometry.land_length;
  const Real front = land_end + geometry.exit_length;

  std::vector<Column> columns;
  add_columns(columns, 0.0, die_entry, cells_along(geometry.container_length, size),
              BoundaryLabel::Container);
  const auto& kinks = profile.breakpoints();
  for (std::size_t k = 0; k + 1 < kinks.size(); ++k)
    add_columns(columns, die_entry + kinks[k], die_entry + kinks[k + 1],
                cells_covering(kinks[k + 1] - kinks[k], size), BoundaryLabel::Die);
  if (geometry.land_length > 0)
    add_columns(columns, die_exit, land_end, cells_along(geometry.land_length, size),
                BoundaryLabel::Die);
  add_columns(columns, land_end, front, cells_along(geometry.exit_length, size),
              BoundaryLabel::FreeExit);
  const int n_rows = cells_along(geometry.entry_half_height, size);
  FF_ASSERT(n_rows > 0, "mesh size must fit the entry half height");
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");

  auto height = [&](Real x) {
    if (x <= die_entry) return geometry.entry_half_height;
    if (x >= die_exit) return geometry.exit_half_height;
    return profile.height(x - die_entry);
  };
  // Lattice x positions: column edges and, for Q2, column midpoints.
  std::vector<Real> lattice_x;
  for (const Column& column : columns)
    for (int s = 0; s < order; ++s)
      lattice_x.push_back(column.left + (column.right - column.left) * s / order);
  lattice_x.push_back(front);
  const int n_x = static_cast<int>(lattice_x.size()), n_y = n_rows * order + 1;

  Mesh<2> mesh;
  mesh.order = order;
  mesh.nodes.resize(2, n_x * n_y);
  for (int j = 0; j < n_y; ++j)
    for (int i = 0; i < n_x; ++i) {
      const Real fraction = static_cast<Real>(j) / (n_y - 1);
      mesh.nodes.col(j * n_x + i) = Point<2>(lattice_x[i], fraction * height(lattice_x[i]));
    }

  const int n_columns = static_cast<int>(columns.size()), n_side = order + 1;
  mesh.cells.resize(n_side * n_side, n_columns * n_rows);
  for (int row = 0; row < n_rows; ++row)
    for (int column = 0; column < n_columns; ++column) {
      const Index cell = row * n_columns + column;
      for (int b = 0; b < n_side; ++b)
        for (int a = 0; a < n_side; ++a)
          mesh.cells(b * n_side + a, cell) = (row * order + b) * n_x + column * order + a;
      if (column == 0) mesh.facets.push_back({cell, 0, BoundaryLabel::Rear});
      if (column + 1 == n_columns) mesh.facets.push_back({cell, 1, BoundaryLabel::Front});
      if (row == 0) mesh.facets.push_back({cell, 2, BoundaryLabel::Symmetry});
      if (row + 1 == n_rows) mesh.facets.push_back({cell, 3, columns[column].top});
    }
  return mesh;
}

/// The square die's land: the first L_land of the exit's free surface touches the die.
void add_square_die_land(const ChannelGeometry& geometry, Mesh<2>& mesh) {
  const Real land_end = geometry.container_length + geometry.land_length;
  for (BoundaryFacet& facet : mesh.facets) {
    if (facet.label != BoundaryLabel::FreeExit) continue;
    const auto face = mesh.face_nodes(facet.local_face);
    const Real middle = 0.5 * (mesh.nodes(0, mesh.cells(face.front(), facet.cell)) +
                               mesh.nodes(0, mesh.cells(face.back(), facet.cell)));
    if (middle < land_end) facet.label = BoundaryLabel::Die;
  }
}

} // namespace

Real die_channel_cell_count(const ChannelGeometry& geometry, Real size) {
  const Real rows_in = geometry.entry_half_height / size;
  if (geometry.die == DieShape::Square) // the container block and the exit block
    return geometry.container_length / size * rows_in +
           geometry.exit_length / size * (geometry.exit_half_height / size);
  // One mapped block: the columns of make_mapped_mesh times H_in/size rows.
  Real columns = (geometry.container_length + geometry.land_length + geometry.exit_length) / size;
  const DieProfile profile(geometry);
  const auto& kinks = profile.breakpoints();
  for (std::size_t k = 0; k + 1 < kinks.size(); ++k)
    columns += std::max<Real>(1, std::ceil((kinks[k + 1] - kinks[k]) / size - 1e-9));
  return columns * rows_in;
}

Real die_exit_position(const ChannelGeometry& geometry) {
  if (geometry.die == DieShape::Square) return geometry.container_length;
  return geometry.container_length + DieProfile(geometry).length();
}

Mesh<2> make_die_channel_mesh(const ChannelGeometry& geometry, Real size, int order) {
  if (geometry.die != DieShape::Square) return make_mapped_mesh(geometry, size, order);
  Mesh<2> mesh = make_channel_mesh(geometry, size, order);
  if (geometry.land_length > 0) add_square_die_land(geometry, mesh);
  return mesh;
}

void free_container_wall(Mesh<2>& mesh) {
  for (BoundaryFacet& facet : mesh.facets)
    if (facet.label == BoundaryLabel::Container) facet.label = BoundaryLabel::FreeEntry;
}

} // namespace formflow::mesh
