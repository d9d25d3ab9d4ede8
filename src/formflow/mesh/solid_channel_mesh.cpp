// SPDX-License-Identifier: MIT
// Which generator makes which solid section.
#include "formflow/mesh/solid_channel_mesh.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/cross_section_mesh.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/extruded_mesh.hpp"
#include "formflow/mesh/rectangle_channel_mesh.hpp"
#include "formflow/mesh/round_square_die_mesh.hpp"
#include "formflow/mesh/swept_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::mesh {

namespace {

int width_layers(const SolidChannel& solid, Real size) {
  return extrusion_layers(solid.entry_half_width, size);
}

/// O-grid cells of the unit quarter disk with n cells along each axis
/// (mesh/cross_section_mesh.hpp): m² in the core, 2·m·k in the curved blocks.
Real quarter_disk_cells(Real radial_cells) {
  const Real core = std::max<Real>(1, std::floor(radial_cells / 2));
  const Real ring = std::max<Real>(1, radial_cells - core);
  return core * core + 2 * core * ring;
}

} // namespace

Mesh<3> make_solid_channel_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                Real size, int order, bool drawing) {
  const bool square = geometry.die == DieShape::Square;
  if (solid.section != ChannelSection::Slab && square) {
    Mesh<3> mesh = solid.section == ChannelSection::Rectangle
                       ? make_rectangle_channel_mesh(geometry, solid, size, order)
                       : make_round_square_die_mesh(geometry, solid, size, order);
    if (drawing)
      for (BoundaryFacet& facet : mesh.facets)
        if (facet.label == BoundaryLabel::Container) facet.label = BoundaryLabel::FreeEntry;
    return mesh;
  }
  Mesh<2> channel = make_die_channel_mesh(geometry, size, order);
  if (drawing) free_container_wall(channel);
  if (solid.section == ChannelSection::Slab)
    return extrude_mesh(channel, solid.thickness, extrusion_layers(solid.thickness, size),
                        BoundaryLabel::Symmetry);
  const int rows = cells_along(geometry.entry_half_height, size);
  FF_ASSERT(rows > 0 && !square, "a swept section needs a mapped channel (case validation)");
  if (solid.section == ChannelSection::Rectangle) {
    const Real h_in = geometry.entry_half_height, h_out = geometry.exit_half_height;
    const Real w_in = solid.entry_half_width, w_out = solid.exit_half_width;
    return sweep_section(
        channel, make_unit_square_section(rows, width_layers(solid, size), order),
        [=](Real height) { return w_out + (w_in - w_out) * (height - h_out) / (h_in - h_out); });
  }
  return sweep_section(channel, make_quarter_disk_section(rows, order),
                       [](Real height) { return height; });
}

Real solid_channel_cell_count(const ChannelGeometry& geometry, const SolidChannel& solid,
                              Real size) {
  const Real plane = die_channel_cell_count(geometry, size);
  const Real rows = geometry.entry_half_height / size;
  switch (solid.section) {
  case ChannelSection::Slab: return plane * extrusion_layers(solid.thickness, size);
  case ChannelSection::Rectangle:
    if (geometry.die == DieShape::Square)
      return (geometry.container_length * geometry.entry_half_height * solid.entry_half_width +
              geometry.exit_length * geometry.exit_half_height * solid.exit_half_width) /
             (size * size * size);
    return plane * width_layers(solid, size);
  case ChannelSection::Round:
    if (geometry.die == DieShape::Square) return round_square_die_cell_count(geometry, solid, size);
    return plane / rows * quarter_disk_cells(std::round(rows));
  case ChannelSection::Profile:
    // Gmsh's tetrahedra of size h fill h³ with ≈ 1.5 cubes' worth of P2 nodes: counted
    // in cubes, as the estimate's dofs are (the bearing's finer cells are left out: a
    // lower bound, like the rest of the estimate).
    return 1.5 *
           profile_model_volume(solid.profile, geometry.container_length, geometry.exit_length) /
           (size * size * size);
  }
  return plane;
}

std::vector<Real> solid_lengths_to_fit(const ChannelGeometry& geometry, const SolidChannel& solid) {
  std::vector<Real> lengths = {geometry.container_length, geometry.entry_half_height,
                               geometry.exit_length};
  const bool square = geometry.die == DieShape::Square;
  if (square) lengths.push_back(geometry.exit_half_height);
  if (geometry.land_length > 0) lengths.push_back(geometry.land_length);
  if (solid.section == ChannelSection::Rectangle) {
    lengths.push_back(solid.entry_half_width);
    if (square) lengths.push_back(solid.exit_half_width);
  }
  // The round billet's square die: the exit rectangle is the O-grid's core.
  if (solid.section == ChannelSection::Round && square) lengths.push_back(solid.exit_half_width);
  return lengths;
}

bool solid_lengths_fit(const ChannelGeometry& geometry, const SolidChannel& solid, Real size) {
  const bool square = geometry.die == DieShape::Square;
  for (Real length : solid_lengths_to_fit(geometry, solid))
    if (cells_along(length, size) <= 0) return false;
  if (cells_along(geometry.exit_half_height, size) >= cells_along(geometry.entry_half_height, size))
    return false;
  if (solid.section == ChannelSection::Round && square)
    return round_square_exit_fits(geometry, solid, size);
  return solid.section != ChannelSection::Rectangle || !square ||
         cells_along(solid.exit_half_width, size) <= cells_along(solid.entry_half_width, size);
}

} // namespace formflow::mesh
