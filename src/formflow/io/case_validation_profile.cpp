// SPDX-License-Identifier: MIT
// Profile cases: defaults, the outline file and the checks (io/case_validation_profile.hpp).
#include "formflow/io/case_validation_profile.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/mesh/profile_die.hpp"

#include <fmt/format.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace formflow::io {

namespace {

using mesh::ChannelSection;

bool is_profile(const Case& case_) {
  return case_.mesh.dimension == 3 && case_.mesh.solid.section == ChannelSection::Profile;
}

/// An outline file is a list of points: a few MB hold 100 000 of them.
constexpr std::uintmax_t max_profile_file_bytes = 8u << 20;
constexpr std::size_t max_profile_file_points = 100000;

} // namespace

void resolve_profile_defaults(Case& case_, const std::function<bool(const std::string&)>& is_set) {
  if (!is_profile(case_)) return;
  if (!is_set("mesh.source")) case_.mesh.source = mesh::MeshSource::Gmsh;
  if (!is_set("mesh.cell")) case_.mesh.cell = mesh::CellKind::Tetrahedron;
  // The billet's wall is faceted (io/case_validation_cad.cpp says why face normals pin it):
  // the half T at h = 2, frictionless, reads 27.02 with face normals, 70 % of it the contact
  // penalty's power, and 8.023 with nodal ones, where that power is 2e-5 of the total.
  if (!is_set("contact.normals")) case_.contact.normals = assembly::ContactNormals::Nodes;
}

void read_profile_file(Case& case_, const std::string& file, int line) {
  const std::string key = "geometry.profile_file";
  if (!case_.mesh.solid.profile.outline.empty())
    throw InputError(file, line, key, "the outline is given twice (geometry.profile is set too)",
                     "keep geometry.profile or geometry.profile_file, not both");
  std::filesystem::path path(case_.profile_file);
  if (!path.is_absolute() && file != "--set" && file != "<default>")
    path = std::filesystem::path(file).parent_path() / path;
  std::error_code error;
  // A FIFO or a device would block or never end: only a regular file is read.
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(file, line, key,
                     fmt::format("\"{}\" is not a readable regular file", path.string()),
                     "give the path of a CSV of `y, z` lines (relative to the case file)");
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error || bytes > max_profile_file_bytes)
    throw InputError(file, line, key,
                     fmt::format("\"{}\" is {} bytes, more than an outline of {} points needs",
                                 path.string(), bytes, max_profile_file_points),
                     fmt::format("an outline file of at most {} MB", max_profile_file_bytes >> 20));
  std::ifstream stream(path, std::ios::binary);
  std::stringstream text;
  text << stream.rdbuf();
  if (!stream.good() && !stream.eof())
    throw InputError(file, line, key, fmt::format("cannot read \"{}\"", path.string()),
                     "check the file's permissions");
  const std::string content = text.str();
  if (content.find('\0') != std::string::npos)
    throw InputError(file, line, key,
                     fmt::format("\"{}\" is not a text file (it holds NUL bytes)", path.string()),
                     "give a CSV of `y, z` lines");
  const mesh::ProfileFileRead read = mesh::read_profile_csv(content, max_profile_file_points);
  // The CSV's own line is the place to fix; its text is not quoted (it may not be a CSV).
  if (!read.problem.empty())
    throw InputError(path.string(), read.line, key, read.problem,
                     "each line `y, z` (two numbers, comma or space separated); a header "
                     "line, blank lines and `#` comments are skipped");
  case_.mesh.solid.profile.outline = read.points;
}

std::optional<KeyRefusal>
profile_case_problem(const Case& case_, const std::function<bool(const std::string&)>& is_set) {
  const auto changed = [&](const std::string& name) {
    const CaseKey* key = find_case_key(name);
    return is_set(name) && key->get(case_) != key->default_value;
  };
  const bool profile = is_profile(case_);
  if (!profile) {
    for (const char* name :
         {"geometry.profile", "geometry.profile_file", "geometry.profile_symmetry",
          "geometry.billet_radius", "geometry.bearing_length", "mesh.bearing_size"})
      if (changed(name))
        return KeyRefusal{{name},
                          "is read only by geometry.dimension = 3 with geometry.section = "
                          "\"profile\"",
                          std::string("set geometry.dimension = 3 and geometry.section = "
                                      "\"profile\", or leave ") +
                              name + " out"};
    return std::nullopt;
  }
  // The plane channel's die is replaced by the flat die: its keys would be read by nothing.
  for (const char* name : {"geometry.entry_half_height", "geometry.exit_half_height",
                           "geometry.die", "geometry.die_angle", "geometry.die_radius",
                           "geometry.die_profile", "geometry.land_length"})
    if (changed(name))
      return KeyRefusal{{name, "geometry.section"},
                        "a profile's billet is geometry.billet_radius and its die is the flat "
                        "die of the outline: the plane channel's die keys are not read",
                        std::string("leave ") + name +
                            " out; the opening is geometry.profile, its wall "
                            "geometry.bearing_length"};
  if (case_.mesh.source != mesh::MeshSource::Gmsh)
    return KeyRefusal{{"mesh.source", "geometry.section"},
                      "a profile's billet, die and extrudate are built and meshed by Gmsh",
                      "leave mesh.source out (or set it to \"gmsh\"); a mesh of your own die "
                      "goes in mesh.file with geometry.section left out"};
  if (case_.mesh.cell != mesh::CellKind::Tetrahedron)
    return KeyRefusal{{"mesh.cell", "geometry.section"},
                      "a profile is meshed in tetrahedra: the flat die's opening is no "
                      "sweepable shape for hexahedra",
                      "leave mesh.cell out (or set it to \"tetrahedron\")"};
  if (case_.process.type == physics::ProcessType::Drawing)
    return KeyRefusal{{"process.type", "geometry.section"},
                      "a profile's billet is pushed by the ram through the flat die",
                      "use process.type = \"extrusion\""};
  const mesh::ProfileDie& die = case_.mesh.solid.profile;
  const bool inline_points = !die.outline.empty() && case_.profile_file.empty();
  if (die.outline.empty())
    return KeyRefusal{{"geometry.profile", "geometry.section"},
                      "geometry.section = \"profile\" needs the product's outline",
                      "e.g. profile = [[0, 0], [4, 0], [4, 1], [0, 1]] in [geometry], or "
                      "profile_file = \"outline.csv\""};
  const std::string outline_key = inline_points ? "geometry.profile" : "geometry.profile_file";
  if (const auto problem = mesh::profile_outline_problem(die))
    return KeyRefusal{{outline_key, "geometry.billet_radius", "geometry.profile_symmetry"},
                      *problem,
                      "the opening must be one simple polygon inside the billet (a hollow "
                      "profile needs a mandrel: not served), symmetric as "
                      "geometry.profile_symmetry says"};
  const std::size_t edges = die.outline.size();
  if (die.bearing_length.size() != 1 && die.bearing_length.size() != edges)
    return KeyRefusal{{"geometry.bearing_length", outline_key},
                      fmt::format("{} bearing lengths for an outline of {} edges",
                                  die.bearing_length.size(), edges),
                      fmt::format("give one length for every edge, or {} (edge k from point k "
                                  "to point k + 1)",
                                  edges)};
  const Real cell = case_.mesh.bearing_cell();
  if (case_.mesh.bearing_size > case_.mesh.size)
    return KeyRefusal{{"mesh.bearing_size", "mesh.size"},
                      fmt::format("the bearing's cells ({}) are larger than the mesh's ({})",
                                  case_.mesh.bearing_size, case_.mesh.size),
                      "make mesh.bearing_size ≤ mesh.size, or leave it out (mesh.size / 2)"};
  for (std::size_t e = 0; e < edges; ++e)
    if (die.bearing(e) < cell)
      return KeyRefusal{
          {"geometry.bearing_length", "mesh.bearing_size", "mesh.size"},
          fmt::format("the bearing of edge {} is {}, shorter than a bearing cell "
                      "({}): no cell could tell its end",
                      e, die.bearing(e), cell),
          fmt::format("make every bearing at least {}, or refine mesh.bearing_size", cell)};
  return std::nullopt;
}

} // namespace formflow::io
