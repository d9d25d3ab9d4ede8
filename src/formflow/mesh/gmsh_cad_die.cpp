// SPDX-License-Identifier: MIT
// A CAD die channel through OpenCASCADE and Gmsh (mesh/gmsh_cad_die.hpp).
#include "formflow/mesh/gmsh_cad_die.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/gmsh_session.hpp"
#include "formflow/mesh/gmsh_solid_groups.hpp"
#include "formflow/mesh/gmsh_solid_mesh.hpp"

#include <fmt/format.h>
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace formflow::mesh {

namespace {

namespace occ = gmsh::model::occ;
using Subject = MeshFileError::Subject;

/// "7 at (x, y, z)" for the surfaces a map leaves out (at most a few named).
std::string surface_list(const std::vector<int>& surfaces) {
  std::string text;
  for (std::size_t k = 0; k < surfaces.size() && k < 8; ++k) {
    double x = 0, y = 0, z = 0;
    occ::getCenterOfMass(2, surfaces[k], x, y, z);
    // OpenCASCADE's centres carry round-off (7e-18 for 0): shown as 0 below 1e-12 of the
    // largest coordinate, so that the list reads like the geometry.
    const double scale = 1e-12 * std::max({std::abs(x), std::abs(y), std::abs(z), 1e-300});
    for (double* coordinate : {&x, &y, &z})
      if (std::abs(*coordinate) < scale) *coordinate = 0.0;
    text +=
        fmt::format("{}{} (centre {:.6g}, {:.6g}, {:.6g})", k ? ", " : "", surfaces[k], x, y, z);
  }
  if (surfaces.size() > 8) text += fmt::format(" and {} more", surfaces.size() - 8);
  return text;
}

} // namespace

Mesh<3> make_gmsh_cad_mesh(const std::string& path, CadFormat format,
                           const std::vector<PhysicalBoundary>& boundaries, Real size, int order) {
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  GmshSession session;
  session.call([&] {
    gmsh::model::add("cad die");
    gmsh::vectorpair imported;
    // The format forced: OpenCASCADE's STEP or BREP reader, never Gmsh's own parsers.
    occ::importShapes(path, imported, true, cad_format_name(format));
    gmsh::vectorpair solids;
    for (const auto& entity : imported)
      if (entity.first == 3) solids.push_back(entity);
    if (solids.empty())
      throw MeshFileError(Subject::File, "", "the file holds no solid (only surfaces or curves)",
                          "export the die channel's material region as one closed solid");
    if (solids.size() > 1) { // glued into one conforming model
      gmsh::vectorpair glued;
      std::vector<gmsh::vectorpair> map;
      occ::fragment({solids.front()}, gmsh::vectorpair(solids.begin() + 1, solids.end()), glued,
                    map);
    }
    occ::synchronize();
    const std::vector<int> boundary = boundary_surfaces();
    std::map<BoundaryLabel, std::vector<int>> parts;
    std::set<int> mapped;
    for (const PhysicalBoundary& entry : boundaries) {
      int tag = 0;
      const bool number = !entry.name.empty() &&
                          entry.name.find_first_not_of("0123456789") == std::string::npos &&
                          entry.name.size() <= 9;
      if (number) tag = std::stoi(entry.name);
      if (!number || std::find(boundary.begin(), boundary.end(), tag) == boundary.end())
        throw MeshFileError(
            Subject::Group, entry.name,
            fmt::format("\"{}\" is not a boundary surface of the CAD solid (its boundary "
                        "surfaces are {})",
                        entry.name, surface_list(boundary)),
            "map the boundary surfaces by their tags, e.g. \"1\" = \"rear\"");
      parts[entry.label].push_back(tag);
      mapped.insert(tag);
    }
    std::vector<int> unmapped;
    for (const int tag : boundary)
      if (!mapped.count(tag)) unmapped.push_back(tag);
    if (!unmapped.empty())
      throw MeshFileError(Subject::Boundaries, "",
                          fmt::format("boundary surface{} {} of the CAD solid {} no part",
                                      unmapped.size() > 1 ? "s" : "", surface_list(unmapped),
                                      unmapped.size() > 1 ? "have" : "has"),
                          "map every boundary surface in [mesh.boundaries], e.g. \"" +
                              std::to_string(unmapped.front()) + "\" = \"die\"");
    add_solid_groups(parts);
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.SecondOrderLinear", 1); // straight edges: no folded cell
    gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 0);
    gmsh::model::mesh::generate(3);
    if (order == 2) gmsh::model::mesh::setOrder(2);
  });
  return solid_mesh_from_gmsh_model(session, {}, order, CellShape::Simplex);
}

} // namespace formflow::mesh
