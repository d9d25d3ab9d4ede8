// SPDX-License-Identifier: MIT
// The flat die of a profile with Gmsh's OpenCASCADE kernel (mesh/gmsh_profile_die.hpp).
#include "formflow/mesh/gmsh_profile_die.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/gmsh_session.hpp"
#include "formflow/mesh/gmsh_solid_groups.hpp"
#include "formflow/mesh/gmsh_solid_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace formflow::mesh {

namespace {

namespace occ = gmsh::model::occ;

using Parts = std::map<BoundaryLabel, std::vector<int>>; // label → surface tags

/// The distinct bearing lengths, ascending, then the extrudate's end: the x offsets from
/// the die face at which the opening's prism is cut.
std::vector<Real> prism_breaks(const ProfileDie& die, Real exit_length) {
  std::vector<Real> breaks = die.bearing_length;
  std::sort(breaks.begin(), breaks.end());
  // Bearings closer than a millionth of the longest are one cut (no sliver layer).
  const Real merge = 1e-6 * die.longest_bearing();
  breaks.erase(
      std::unique(breaks.begin(), breaks.end(), [merge](Real a, Real b) { return b - a <= merge; }),
      breaks.end());
  breaks.push_back(die.longest_bearing() + exit_length);
  return breaks;
}

/// The opening at x = L_c as a plane surface of the whole outline.
int add_opening(const ProfileDie& die, Real x) {
  std::vector<int> points, lines;
  for (const auto& [y, z] : die.outline) points.push_back(occ::addPoint(x, y, z));
  for (std::size_t k = 0; k < points.size(); ++k)
    lines.push_back(occ::addLine(points[k], points[(k + 1) % points.size()]));
  return occ::addPlaneSurface({occ::addCurveLoop(lines)});
}

/// The volumes of the whole section: the billet, then the prism's layers.
gmsh::vectorpair add_whole_solid(const ChannelGeometry& geometry, const ProfileDie& die) {
  const Real lc = geometry.container_length;
  gmsh::vectorpair volumes = {{3, occ::addCylinder(0, 0, 0, lc, 0, 0, die.billet_radius)}};
  int face = add_opening(die, lc);
  Real offset = 0.0;
  for (const Real next : prism_breaks(die, geometry.exit_length)) {
    gmsh::vectorpair out;
    occ::extrude({{2, face}}, next - offset, 0, 0, out);
    face = out.at(0).second; // OCC's extrude lists the top, then the volume
    volumes.push_back(out.at(1));
    offset = next;
  }
  return volumes;
}

/// Each volume cut to the model's side of the symmetry planes (y ≥ 0, and z ≥ 0).
gmsh::vectorpair cut_to_symmetry(const gmsh::vectorpair& volumes, const ChannelGeometry& geometry,
                                 const ProfileDie& die) {
  if (die.symmetry == ProfileSymmetry::None) return volumes;
  const Real r = 2 * die.billet_radius, length = 2 * (geometry.container_length +
                                                      die.longest_bearing() + geometry.exit_length);
  const bool quarter = die.symmetry == ProfileSymmetry::YZ;
  gmsh::vectorpair kept;
  for (const auto& volume : volumes) {
    const int box = occ::addBox(-length, 0, quarter ? 0 : -r, 2 * length, r, quarter ? r : 2 * r);
    gmsh::vectorpair out;
    std::vector<gmsh::vectorpair> map;
    occ::intersect({volume}, {{3, box}}, out, map);
    kept.insert(kept.end(), out.begin(), out.end());
  }
  return kept;
}

/// The part of a boundary surface, from where its centre of mass lies and which plane
/// its bounding box is flat in.
BoundaryLabel profile_part(const ChannelGeometry& geometry, const ProfileDie& die, int surface,
                           Real tolerance) {
  std::array<double, 3> c{};
  occ::getCenterOfMass(2, surface, c[0], c[1], c[2]);
  std::array<double, 6> box{};
  gmsh::model::getBoundingBox(2, surface, box[0], box[1], box[2], box[3], box[4], box[5]);
  const auto flat = [&](int axis) {
    return box[static_cast<std::size_t>(axis + 3)] - box[static_cast<std::size_t>(axis)] <=
           tolerance;
  };
  const Real lc = geometry.container_length;
  const Real x_end = lc + die.longest_bearing() + geometry.exit_length;
  if (flat(0)) {
    if (std::abs(c[0]) <= tolerance) return BoundaryLabel::Rear;
    if (std::abs(c[0] - x_end) <= tolerance) return BoundaryLabel::Front;
    FF_ASSERT(std::abs(c[0] - lc) <= tolerance, "a plane x = const on the boundary");
    return BoundaryLabel::Die; // the flat face around the opening
  }
  if (die.symmetry != ProfileSymmetry::None && flat(1) && std::abs(c[1]) <= tolerance)
    return BoundaryLabel::Symmetry;
  if (die.symmetry == ProfileSymmetry::YZ && flat(2) && std::abs(c[2]) <= tolerance)
    return BoundaryLabel::Symmetry;
  if (c[0] < lc) return BoundaryLabel::Container;
  // A wall of the opening's prism: the centre lies on the outline edge it was swept from.
  const std::size_t edge = nearest_edge(die, {c[1], c[2]});
  FF_ASSERT(distance_to_edge(die, edge, {c[1], c[2]}) <= 1e3 * tolerance,
            "a prism wall lies on an outline edge");
  return box[3] <= lc + die.bearing(edge) + tolerance ? BoundaryLabel::Die
                                                      : BoundaryLabel::FreeExit;
}

/// The bearing walls (die surfaces beyond the die face), for the size field.
std::vector<int> bearing_walls(const Parts& parts, Real lc, Real tolerance) {
  std::vector<int> walls;
  const auto die = parts.find(BoundaryLabel::Die);
  if (die == parts.end()) return walls;
  for (const int surface : die->second) {
    std::array<double, 6> box{};
    gmsh::model::getBoundingBox(2, surface, box[0], box[1], box[2], box[3], box[4], box[5]);
    if (box[3] > lc + tolerance) walls.push_back(surface);
  }
  return walls;
}

/// Cells of `bearing_size` within that distance of the bearing walls' edges (the die
/// opening, the bearing's end, the walls' corners), growing linearly to `size` at 4 `size`
/// from them: the bearing decides the exit speeds, the billet's far part carries a slow,
/// smooth flow. (Gmsh 4.8 measures the distance to sampled curves, not to surfaces.)
void set_bearing_field(const std::vector<int>& walls, Real size, Real bearing_size) {
  namespace field = gmsh::model::mesh::field;
  gmsh::vectorpair wall_tags, curves;
  for (const int wall : walls) wall_tags.emplace_back(2, wall);
  gmsh::model::getBoundary(wall_tags, curves, false, false, false);
  std::vector<double> curve_tags;
  double longest = 0.0;
  for (const auto& [dim, tag] : curves) {
    if (std::find(curve_tags.begin(), curve_tags.end(), std::abs(tag)) != curve_tags.end())
      continue;
    curve_tags.push_back(std::abs(tag));
    std::array<double, 6> box{};
    gmsh::model::getBoundingBox(1, std::abs(tag), box[0], box[1], box[2], box[3], box[4], box[5]);
    longest = std::max(longest, std::hypot(box[3] - box[0], box[4] - box[1], box[5] - box[2]));
  }
  const int distance = field::add("Distance");
  field::setNumbers(distance, "EdgesList", curve_tags);
  // Samples half a bearing cell apart along the longest curve (bounded: the field is
  // evaluated at every node Gmsh places).
  field::setNumber(distance, "NNodesByEdge",
                   std::clamp(std::ceil(2 * longest / bearing_size), 10.0, 2000.0));
  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "IField", distance);
  field::setNumber(threshold, "LcMin", bearing_size);
  field::setNumber(threshold, "LcMax", size);
  field::setNumber(threshold, "DistMin", bearing_size);
  field::setNumber(threshold, "DistMax", 4 * size);
  field::setAsBackgroundMesh(threshold);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", bearing_size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
}

} // namespace

Mesh<3> make_gmsh_profile_die_mesh(const ChannelGeometry& geometry, const ProfileDie& die,
                                   Real size, Real bearing_size, int order) {
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  FF_ASSERT(!profile_outline_problem(die), "validated: a simple outline inside the billet");
  GmshSession session;
  session.call([&] {
    gmsh::model::add("profile die");
    gmsh::vectorpair volumes = cut_to_symmetry(add_whole_solid(geometry, die), geometry, die);
    // One conforming model: the billet's end face is split along the opening, the
    // prism's layers share their faces.
    gmsh::vectorpair glued;
    std::vector<gmsh::vectorpair> map;
    occ::fragment({volumes.front()}, gmsh::vectorpair(volumes.begin() + 1, volumes.end()), glued,
                  map);
    occ::synchronize();
    const Real extent =
        std::max(die.billet_radius,
                 geometry.container_length + die.longest_bearing() + geometry.exit_length);
    // OpenCASCADE's bounding boxes are widened by its shape tolerance (1e-7).
    const Real tolerance = 1e-6 * std::max(1.0, extent);
    Parts parts;
    for (const int tag : boundary_surfaces())
      parts[profile_part(geometry, die, tag, tolerance)].push_back(tag);
    add_solid_groups(parts);
    set_bearing_field(bearing_walls(parts, geometry.container_length, tolerance), size,
                      bearing_size);
    gmsh::option::setNumber("Mesh.SecondOrderLinear", 1); // straight edges: no folded cell
    gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 0);
    gmsh::model::mesh::generate(3);
    if (order == 2) gmsh::model::mesh::setOrder(2);
  });
  try {
    return solid_mesh_from_gmsh_model(session, {}, order, CellShape::Simplex);
  } catch (const MeshFileError& error) {
    throw InternalError("Gmsh profile die mesh: " + error.message); // our geometry: a bug
  }
}

} // namespace formflow::mesh
