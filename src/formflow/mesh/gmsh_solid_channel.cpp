// SPDX-License-Identifier: MIT
// Solid die channels from Gmsh: the plane channel or a rectangle cross-section
// extruded into hexahedra (recombined extrusion; cut into tetrahedra on request), parts as
// physical surfaces.
#include "formflow/mesh/gmsh_solid_channel.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/extruded_mesh.hpp"
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/mesh/gmsh_session.hpp"
#include "formflow/mesh/gmsh_solid_groups.hpp"
#include "formflow/mesh/gmsh_solid_mesh.hpp"
#include "formflow/mesh/tetrahedral_split.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace formflow::mesh {

namespace {

namespace geo = gmsh::model::geo;

using Parts = std::map<BoundaryLabel, std::vector<int>>; // label → surface tags

/// Layers of about `size` over `length`, at least one.
int layers_over(Real length, Real size) {
  return std::max(1, static_cast<int>(std::lround(length / size)));
}

/// The plane channel extruded over the thickness: the lateral surfaces follow
/// the base surface's curve loop (Gmsh's extrude returns top, volume, then one
/// lateral surface per boundary curve, in order), so each keeps its curve's part.
int add_slab(const ChannelGeometry& geometry, const SolidChannel& solid, Real size, Parts& parts) {
  const ChannelModel plane =
      add_channel_geometry(geometry, die_face_polyline(geometry, size), size);
  gmsh::vectorpair out;
  geo::extrude({{2, plane.surface}}, 0.0, 0.0, solid.thickness, out,
               {extrusion_layers(solid.thickness, size)}, {}, true);
  std::size_t lateral = 2;
  for (const auto& [label, curves] : plane.parts)
    for (std::size_t k = 0; k < curves.size(); ++k)
      parts[label].push_back(out.at(lateral++).second);
  FF_ASSERT(lateral == out.size(), "Gmsh's extrusion returned an unexpected surface count");
  parts[BoundaryLabel::Symmetry].push_back(plane.surface); // z = 0
  parts[BoundaryLabel::Symmetry].push_back(out[0].second); // z = thickness
  return out[1].second;
}

/// A rectangle in the plane x = 0 from the corner points (tags) given counter-clockwise.
int add_rectangle(int a, int b, int c, int d, std::map<std::pair<int, int>, int>& lines) {
  const auto line = [&lines](int p, int q) {
    if (const auto found = lines.find({q, p}); found != lines.end()) return -found->second;
    if (const auto found = lines.find({p, q}); found != lines.end()) return found->second;
    return lines[{p, q}] = geo::addLine(p, q);
  };
  return geo::addPlaneSurface(
      {geo::addCurveLoop({line(a, b), line(b, c), line(c, d), line(d, a)})});
}

/// The rectangle through the square die: the cross-section's four rectangles
/// extruded together over the container, the exit's one then over the land and
/// the exit. The parts are classified after synchronisation (classify_boundary).
void add_rectangle_square_die(const ChannelGeometry& geometry, const SolidChannel& solid,
                              Real size) {
  const Real h_in = geometry.entry_half_height, h_out = geometry.exit_half_height;
  const Real w_in = solid.entry_half_width, w_out = solid.exit_half_width;
  // (y, z) lattice of the cross-section at x = 0: y ∈ {0, H_out, H_in}, z ∈ {0, W_out, W_in}.
  const std::array<Real, 3> ys = {0.0, h_out, h_in}, zs = {0.0, w_out, w_in};
  std::array<std::array<int, 3>, 3> point{};
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) point[j][k] = geo::addPoint(0.0, ys[j], zs[k], size);
  std::map<std::pair<int, int>, int> lines;
  std::vector<int> section;
  int exit_section = 0;
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) {
      if (ys[j + 1] - ys[j] <= 0 || zs[k + 1] - zs[k] <= 0) continue; // W_out = W_in: no side block
      const int surface =
          add_rectangle(point[j][k], point[j + 1][k], point[j + 1][k + 1], point[j][k + 1], lines);
      section.push_back(surface);
      if (j == 0 && k == 0) exit_section = surface;
    }
  gmsh::vectorpair dim_tags;
  for (const int surface : section) dim_tags.emplace_back(2, surface);
  gmsh::vectorpair container;
  geo::extrude(dim_tags, geometry.container_length, 0.0, 0.0, container,
               {layers_over(geometry.container_length, size)}, {}, true);
  // Gmsh's extrude lists, per input surface, its top then its volume then the laterals:
  // the exit's rectangle is the first input, so its top is container[0].
  int face = container.at(0).second;
  FF_ASSERT(exit_section == section.front(), "the exit's rectangle is the first block");
  for (const Real length : {geometry.land_length, geometry.exit_length}) {
    if (length <= 0) continue;
    gmsh::vectorpair out;
    geo::extrude({{2, face}}, length, 0.0, 0.0, out, {layers_over(length, size)}, {}, true);
    face = out.at(0).second;
  }
}

/// The part of a boundary surface of the rectangle by where it lies: planes of
/// the bounding box (the die faces are planes x = const, y = const, z = const).
BoundaryLabel rectangle_part(const ChannelGeometry& geometry, const SolidChannel& solid,
                             const std::array<double, 6>& box) {
  const Real tolerance = 1e-9 * (geometry.container_length + geometry.entry_half_height);
  const auto flat = [&](int axis) {
    return box[static_cast<std::size_t>(axis + 3)] - box[static_cast<std::size_t>(axis)] <=
           tolerance;
  };
  const auto at = [&](int axis, Real value) {
    return flat(axis) && std::abs(box[static_cast<std::size_t>(axis)] - value) <= tolerance;
  };
  const Real die_end = geometry.container_length + geometry.land_length;
  if (at(0, 0.0)) return BoundaryLabel::Rear;
  if (at(0, die_end + geometry.exit_length)) return BoundaryLabel::Front;
  if (at(0, geometry.container_length)) return BoundaryLabel::Die;
  if (at(1, 0.0) || at(2, 0.0)) return BoundaryLabel::Symmetry;
  if (at(1, geometry.entry_half_height) || at(2, solid.entry_half_width))
    return BoundaryLabel::Container;
  FF_ASSERT(at(1, geometry.exit_half_height) || at(2, solid.exit_half_width),
            "a rectangle's boundary surface is not on a channel plane");
  return box[3] <= die_end + tolerance ? BoundaryLabel::Die : BoundaryLabel::FreeExit; // the land
}

/// Surfaces on the boundary (one adjacent volume) of the rectangle, by part.
Parts classify_boundary(const ChannelGeometry& geometry, const SolidChannel& solid) {
  Parts parts;
  for (const int tag : boundary_surfaces()) {
    std::array<double, 6> box{};
    gmsh::model::getBoundingBox(2, tag, box[0], box[1], box[2], box[3], box[4], box[5]);
    parts[rectangle_part(geometry, solid, box)].push_back(tag);
  }
  return parts;
}

} // namespace

Mesh<3> make_gmsh_solid_channel_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                     Real size, int order, bool drawing, CellShape shape) {
  FF_ASSERT(gmsh_builds_solid_channel(solid, geometry.die), "validated: a section Gmsh builds");
  FF_ASSERT(solid.section != ChannelSection::Profile, "a profile has its own builder");
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  GmshSession session;
  session.call([&] {
    gmsh::model::add("solid channel");
    Parts parts;
    if (solid.section == ChannelSection::Slab) {
      add_slab(geometry, solid, size, parts);
      geo::synchronize();
    } else {
      add_rectangle_square_die(geometry, solid, size);
      geo::synchronize();
      parts = classify_boundary(geometry, solid);
    }
    add_solid_groups(parts);
    set_recombined_quadrilateral_options(size);
    gmsh::model::mesh::generate(3);
    if (order == 2) gmsh::model::mesh::setOrder(2);
  });
  Mesh<3> mesh;
  try {
    mesh = solid_mesh_from_gmsh_model(session, {}, order); // the groups carry the part names
  } catch (const MeshFileError& error) {
    throw InternalError("Gmsh solid channel mesh: " + error.message); // our geometry: a bug
  }
  if (drawing)
    for (BoundaryFacet& facet : mesh.facets)
      if (facet.label == BoundaryLabel::Container) facet.label = BoundaryLabel::FreeEntry;
  // Tetrahedra: the same cross-section and layers as the hexahedra, each cut conformingly
  // (mesh/tetrahedral_split.hpp), so that a tetrahedral and a hexahedral run share their
  // vertices.
  if (shape == CellShape::Simplex) return split_into_tetrahedra(mesh, false);
  return mesh;
}

} // namespace formflow::mesh
