// SPDX-License-Identifier: MIT
// Refusals of three-dimensional cases that cannot run yet (issue 15, first slice).
#include "formflow/io/case_validation_3d.hpp"

#include "formflow/io/case_keys.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/gmsh_solid_channel.hpp"
#include "formflow/mesh/round_square_die_mesh.hpp"

#include <array>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

namespace formflow::io {

namespace {

using mesh::ChannelSection;

/// A solid-channel key set by the user to a value other than its default in a case
/// that does not read it (its default is harmless: the reference's block of every
/// key at its default must load, docs/case-reference.md).
std::optional<KeyRefusal> unused_solid_key(const Case& case_,
                                           const std::function<bool(const std::string&)>& is_set) {
  const auto changed = [&](const std::string& name) {
    const CaseKey* key = find_case_key(name);
    return is_set(name) && key->get(case_) != key->default_value;
  };
  const bool solid = case_.mesh.dimension == 3;
  const ChannelSection section = case_.mesh.solid.section;
  if (!solid && changed("geometry.section"))
    return KeyRefusal{{"geometry.section"},
                      "a section is the cross-section of a solid channel, and "
                      "geometry.dimension = 2 makes the plane one",
                      "set geometry.dimension = 3 for a solid channel, or leave geometry.section "
                      "out"};
  const bool slab = solid && section == ChannelSection::Slab;
  const bool rectangle = solid && section == ChannelSection::Rectangle;
  const bool round_square = solid && section == ChannelSection::Round &&
                            case_.mesh.geometry.die == mesh::DieShape::Square;
  struct Use {
    const char* key;
    bool used;
    const char* by;
  };
  const std::array<Use, 3> uses = {{{"geometry.thickness", slab, "\"slab\""},
                                    {"geometry.entry_half_width", rectangle, "\"rectangle\""},
                                    {"geometry.exit_half_width", rectangle || round_square,
                                     "\"rectangle\" (or \"round\" with geometry.die = "
                                     "\"square\")"}}};
  for (const Use& use : uses)
    if (!use.used && changed(use.key))
      return KeyRefusal{
          {use.key},
          std::string("is read only by geometry.dimension = 3 with geometry.section = ") + use.by,
          std::string("set geometry.dimension = 3 and geometry.section = ") + use.by +
              ", or leave " + use.key + " out"};
  return std::nullopt;
}

/// What a solid case asks that the solid run does not do yet.
std::optional<KeyRefusal> unsupported_in_3d(const Case& case_) {
  if (case_.mesh.dimension != 3) return std::nullopt;
  if (case_.symmetry == physics::Symmetry::Axisymmetric)
    return KeyRefusal{{"geometry.symmetry", "geometry.dimension"},
                      "the axisymmetric model is two-dimensional (y = r in the meridian plane)",
                      "use geometry.dimension = 2 with geometry.symmetry = \"axisymmetric\", or "
                      "geometry.symmetry = \"plane\" in 3D"};
  if (case_.mesh.source == mesh::MeshSource::Gmsh &&
      !mesh::gmsh_builds_solid_channel(case_.mesh.solid, case_.mesh.geometry.die))
    return KeyRefusal{{"mesh.source", "geometry.section"},
                      "Gmsh builds the solid slab (every die) and the rectangle with the square "
                      "die only; this section and die come from the structured generator",
                      "use mesh.source = \"structured\", or \"file\" with a .msh of hexahedra"};
  return std::nullopt;
}

/// The rectangle's half widths: no wider exit than container, and cells of
/// mesh.size across them (the square die's lattice needs both, a swept die the
/// container's: mesh/solid_channel_mesh.hpp).
std::optional<KeyRefusal> rectangle_problem(const Case& case_) {
  if (case_.mesh.dimension != 3 || case_.mesh.solid.section != ChannelSection::Rectangle)
    return std::nullopt;
  const mesh::SolidChannel& solid = case_.mesh.solid;
  if (!(solid.exit_half_width <= solid.entry_half_width))
    return KeyRefusal{{"geometry.exit_half_width", "geometry.entry_half_width"},
                      fmt::format("the product ({} wide) is wider than the billet ({})",
                                  2 * solid.exit_half_width, 2 * solid.entry_half_width),
                      "make geometry.exit_half_width ≤ geometry.entry_half_width"};
  // Gmsh chooses its own cross-section cells; a file's mesh has no mesh.size.
  if (case_.mesh.source != mesh::MeshSource::Structured) return std::nullopt;
  const Real size = case_.mesh.size;
  const bool square = case_.mesh.geometry.die == mesh::DieShape::Square;
  for (const char* name : {"geometry.entry_half_width", "geometry.exit_half_width"}) {
    const bool exit = std::string_view(name) == "geometry.exit_half_width";
    if (exit && !square) continue;
    const Real width = exit ? solid.exit_half_width : solid.entry_half_width;
    if (mesh::cells_along(width, size) > 0) continue;
    return KeyRefusal{{name, "mesh.size"},
                      fmt::format("the half width {} is not a multiple of mesh.size = {} "
                                  "({:.6g} cells)",
                                  width, size, width / size),
                      square ? "with the square die both half widths are cut into cells of "
                               "mesh.size: make them multiples of it"
                             : "the container's half width is cut into cells of mesh.size: "
                               "make it a multiple of it"};
  }
  return std::nullopt;
}

/// A round billet through the square die: the exit rectangle H_out × W_out is the
/// O-grid's core, so it must fit inside the container's circle with half a cell
/// to spare at its corner, and mesh.size must fit both its half sides
/// (mesh/round_square_die_mesh.hpp).
std::optional<KeyRefusal> round_square_problem(const Case& case_) {
  if (case_.mesh.dimension != 3 || case_.mesh.solid.section != ChannelSection::Round ||
      case_.mesh.geometry.die != mesh::DieShape::Square ||
      case_.mesh.source != mesh::MeshSource::Structured) // a file's mesh has its own section
    return std::nullopt;
  const mesh::ChannelGeometry& geometry = case_.mesh.geometry;
  const mesh::SolidChannel& solid = case_.mesh.solid;
  const Real size = case_.mesh.size;
  if (!mesh::round_square_exit_fits(geometry, solid, size))
    return KeyRefusal{
        {"geometry.exit_half_width", "geometry.exit_half_height", "geometry.entry_half_height"},
        fmt::format("the exit's corner ({}, {}) is at radius {:.6g}, not inside the billet's "
                    "radius {} by half a cell (mesh.size / 2 = {})",
                    geometry.exit_half_height, solid.exit_half_width,
                    std::hypot(geometry.exit_half_height, solid.exit_half_width),
                    geometry.entry_half_height, 0.5 * size),
        "the square die's exit must lie inside the round container: make "
        "√(exit_half_height² + exit_half_width²) ≤ entry_half_height − mesh.size/2"};
  if (mesh::cells_along(solid.exit_half_width, size) <= 0)
    return KeyRefusal{{"geometry.exit_half_width", "mesh.size"},
                      fmt::format("the half width {} is not a multiple of mesh.size = {} "
                                  "({:.6g} cells)",
                                  solid.exit_half_width, size, solid.exit_half_width / size),
                      "the square die's exit rectangle is cut into cells of mesh.size: make "
                      "geometry.exit_half_width a multiple of it"};
  return std::nullopt;
}

} // namespace

std::optional<KeyRefusal>
solid_case_problem(const Case& case_, const std::function<bool(const std::string&)>& is_set) {
  if (auto refusal = unused_solid_key(case_, is_set)) return refusal;
  if (auto refusal = unsupported_in_3d(case_)) return refusal;
  if (auto refusal = rectangle_problem(case_)) return refusal;
  return round_square_problem(case_);
}

} // namespace formflow::io
