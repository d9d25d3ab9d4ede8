// SPDX-License-Identifier: MIT
// Turning mesh.source / mesh.file / mesh.boundaries into a checked mesh.
#include "formflow/io/mesh_input.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/io/case_validation_simplex.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/simplex_split.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"
#include "formflow/mesh/tetrahedral_split.hpp"
#if FORMFLOW_WITH_GMSH
#include "formflow/mesh/cad_file.hpp"
#include "formflow/mesh/die_face.hpp"
#include "formflow/mesh/facet_axis.hpp"
#include "formflow/mesh/gmsh_meshers.hpp"
#include "formflow/mesh/gmsh_session.hpp"
#include "formflow/mesh/gmsh_solid_channel.hpp"
#endif

#include <fmt/format.h>

#include <filesystem>
#include <string_view>

namespace formflow::io {

namespace {

#if FORMFLOW_WITH_GMSH
/// Where `name` was set; for a key left at its default, where `fallback` was.
Case::KeyLocation location_of(const Case& case_, const std::string& name,
                              const std::string& fallback = "mesh.file") {
  for (const std::string& key : {name, fallback})
    if (const auto found = case_.key_locations.find(key); found != case_.key_locations.end())
      return found->second;
  return {case_.source, 0};
}

/// mesh.file (or `key`'s path) as Gmsh should open it: relative paths start at the case
/// file's directory.
std::string resolved_mesh_path(const Case& case_, const mesh::MeshSpec& spec,
                               const std::string& key = "mesh.file") {
  const std::filesystem::path path(key == "mesh.file" ? spec.file : spec.cad_file);
  const std::string set_in = location_of(case_, key).file;
  if (path.is_absolute() || set_in == "--set" || set_in == "<default>") return path.string();
  return (std::filesystem::path(set_in).parent_path() / path).string();
}

/// "(x, y)" or "(x, y, z)", 6 significant digits.
template <int dim> std::string point_text(const Point<dim>& p) {
  if constexpr (dim == 2)
    return fmt::format("({:.6g}, {:.6g})", p.x(), p.y());
  else
    return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x(), p.y(), p.z());
}

/// Checks the Jacobian at the Gauss points of the full rule, where the solver
/// evaluates it, and at the cell's nodes: a collapsed edge (two corners in one
/// place) or a corner angle of 180° or more has det J ≤ 0 at a corner only,
/// while every Gauss point can still be positive.
template <int dim>
void check_jacobians(const Case& case_, const mesh::MeshSpec& spec, const mesh::Mesh<dim>& mesh) {
  fem::CellValues<dim> at_gauss(mesh.cell_type(), fem::full_rule<dim>(mesh.cell_type()));
  fem::CellValues<dim> at_nodes(mesh.cell_type(), fem::node_points<dim>(mesh.cell_type()));
  typename fem::CellValues<dim>::Gradients coordinates(dim, mesh.nodes_per_cell());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, cell));
    const bool gauss_valid = at_gauss.reinit(coordinates);
    if (gauss_valid && at_nodes.reinit(coordinates)) continue;
    const Point<dim> centre = coordinates.rowwise().mean();
    const Case::KeyLocation where = location_of(case_, "mesh.file");
    throw InputError(
        where.file, where.line, "mesh.file",
        fmt::format("{}: cell {} (centre {}) is inverted, tangled or "
                    "degenerate: its Jacobian is not positive at a {}",
                    spec.file, cell, point_text<dim>(centre),
                    gauss_valid ? "node (a collapsed edge or a corner angle ≥ 180°)"
                                : "Gauss point"),
        mesh.is_simplex()
            ? std::string("fix the mesh: every ") + (dim == 2 ? "triangle" : "tetrahedron") +
                  " must have a positive volume, and curved (second-order) edges "
                  "must not fold it"
        : dim == 2 ? "fix the mesh: every quadrilateral must be convex enough that its "
                     "isoparametric map is one-to-one"
                   : "fix the mesh: every hexahedron must be convex enough that its "
                     "isoparametric map is one-to-one (no face folded, no corner "
                     "pulled through the opposite face)");
  }
}

std::vector<mesh::PhysicalBoundary> boundary_map(const mesh::MeshSpec& spec) {
  std::vector<mesh::PhysicalBoundary> map; // empty: the physical names are the part names
  for (const auto& [name, part] : spec.boundaries)
    map.push_back({name, *mesh::label_from_name(part)}); // validated by the key table
  return map;
}

/// The tetrahedra of mesh.cad_file's solid: the file checked as data first, then read by
/// OpenCASCADE and meshed by Gmsh; what is wrong with it blames the key to change.
mesh::Mesh<3> read_cad_solid(const Case& case_, const mesh::MeshSpec& spec) {
  using Subject = mesh::MeshFileError::Subject;
  const std::string path = resolved_mesh_path(case_, spec, "mesh.cad_file");
  const Case::KeyLocation file_at = location_of(case_, "mesh.cad_file");
  const mesh::CadFileCheck check = mesh::check_cad_file(path);
  if (!check.format)
    throw InputError(file_at.file, file_at.line, "mesh.cad_file", check.problem, check.hint);
  try {
    return mesh::gmsh_meshers().cad_mesh(path, *check.format, boundary_map(spec), spec.size,
                                         fem::element_order(case_.element));
  } catch (const mesh::MeshFileError& error) {
    std::string key = "mesh.cad_file";
    if (error.subject == Subject::Boundaries) key = "mesh.boundaries";
    if (error.subject == Subject::Group) key = "mesh.boundaries." + error.group;
    const Case::KeyLocation where =
        location_of(case_, key, key == "mesh.cad_file" ? "mesh.cad_file" : "mesh.boundaries");
    throw InputError(where.file, where.line, key,
                     fmt::format("{}: {}", spec.cad_file, error.message), error.hint);
  } catch (const mesh::GmshFailure& failure) {
    throw InputError(file_at.file, file_at.line, "mesh.cad_file",
                     fmt::format("{}: OpenCASCADE or Gmsh could not read or mesh it: {}",
                                 spec.cad_file, failure.what()),
                     "check the solid is closed and valid in the CAD program; a smaller "
                     "mesh.size resolves thin features");
  }
}

/// The file's cells: quadrilaterals for geometry.dimension = 2, hexahedra for 3.
template <int dim> mesh::Mesh<dim> read_mesh_file(const Case& case_, const mesh::MeshSpec& spec) {
  using Subject = mesh::MeshFileError::Subject;
  try {
    if constexpr (dim == 2)
      return mesh::gmsh_meshers().read_mesh(resolved_mesh_path(case_, spec), boundary_map(spec),
                                            fem::element_order(case_.element),
                                            mesh::shape_of(spec.cell));
    else
      return mesh::gmsh_meshers().read_solid_mesh(
          resolved_mesh_path(case_, spec), boundary_map(spec), fem::element_order(case_.element),
          mesh::shape_of(spec.cell));
  } catch (const mesh::MeshFileError& error) {
    std::string key = "mesh.file";
    if (error.subject == Subject::Element) key = "mesh.element";
    if (error.subject == Subject::Cell) key = "mesh.cell";
    if (error.subject == Subject::Boundaries) key = "mesh.boundaries";
    if (error.subject == Subject::Group) key = "mesh.boundaries." + error.group;
    // A key at its default has no line: blame the line of mesh.file (or of the map).
    const Case::KeyLocation where = location_of(
        case_, key, key.rfind("mesh.boundaries.", 0) == 0 ? "mesh.boundaries" : "mesh.file");
    const std::string message = error.subject == Subject::File
                                    ? error.message
                                    : fmt::format("{}: {}", spec.file, error.message);
    throw InputError(where.file, where.line, key, message, error.hint);
  }
}

/// u_N = 0 on a symmetry facet is imposed on the component along its normal axis
/// (assembly/constraints.hpp): a tilted or curved symmetry line cannot be.
template <int dim>
void check_symmetry_planes(const Case& case_, const mesh::MeshSpec& spec,
                           const mesh::Mesh<dim>& mesh) {
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != mesh::BoundaryLabel::Symmetry || mesh::facet_normal_axis(mesh, facet))
      continue;
    Point<dim> centre = Point<dim>::Zero();
    const std::vector<int> nodes = mesh.face_nodes(facet.local_face);
    for (int local : nodes)
      centre += mesh.nodes.col(mesh.cells(local, facet.cell)) / static_cast<Real>(nodes.size());
    const Case::KeyLocation where = location_of(case_, "mesh.boundaries");
    const std::string_view what = dim == 2 ? "line" : "plane";
    throw InputError(where.file, where.line, "mesh.boundaries",
                     fmt::format("{}: a \"symmetry\" facet of cell {} (centre {}) is "
                                 "not on a {}",
                                 spec.file, facet.cell, point_text<dim>(centre),
                                 dim == 2 ? "line x = const or y = const"
                                          : "plane x = const, y = const or z = const"),
                     fmt::format("a symmetry {} must be flat and normal to an axis (the symmetry "
                                 "condition fixes the velocity component along its normal)",
                                 what));
  }
}

/// The part that carries the process speed must exist, or nothing drives the flow.
template <int dim>
void check_driven_part(const Case& case_, const mesh::MeshSpec& spec, const mesh::Mesh<dim>& mesh) {
  const bool extrusion = case_.process.type == physics::ProcessType::Extrusion;
  const mesh::BoundaryLabel driven =
      extrusion ? mesh::BoundaryLabel::Rear : mesh::BoundaryLabel::Front;
  for (const mesh::BoundaryFacet& facet : mesh.facets)
    if (facet.label == driven) return;
  const Case::KeyLocation where = location_of(case_, "mesh.boundaries");
  throw InputError(where.file, where.line, "mesh.boundaries",
                   fmt::format("{}: no boundary facet is \"{}\", where {} drives the flow",
                               spec.file, mesh::label_name(driven),
                               extrusion ? "the ram of the extrusion" : "the pull of the drawing"),
                   fmt::format("map the physical {} of that end to \"{}\"",
                               dim == 2 ? "curve" : "surface", mesh::label_name(driven)));
}
#endif

} // namespace

mesh::AnyMesh load_mesh(const Case& case_, const mesh::MeshSpec& spec) {
  const int order = fem::element_order(case_.element);
  const bool drawing = case_.process.type == physics::ProcessType::Drawing;
  const mesh::CellType cells = case_cell_type(case_);
  if (spec.source == mesh::MeshSource::Structured) {
    // Simplices: each square cut along a diagonal, each hexahedron into tetrahedra.
    if (spec.dimension == 3) { // every section: io/case_validation_3d.cpp checked what it needs
      mesh::Mesh<3> mesh =
          mesh::make_solid_channel_mesh(spec.geometry, spec.solid, spec.size, order, drawing);
      if (cells.is_simplex()) return mesh::split_into_tetrahedra(mesh, cells.bubbles);
      return mesh;
    }
    mesh::Mesh<2> mesh = mesh::make_die_channel_mesh(spec.geometry, spec.size, order);
    if (drawing) mesh::free_container_wall(mesh);
    if (cells.is_simplex()) return mesh::split_into_triangles(mesh, cells.bubbles);
    return mesh;
  }
#if FORMFLOW_WITH_GMSH
  if (spec.source == mesh::MeshSource::Gmsh) {
    if (spec.dimension == 3 && spec.solid.section == mesh::ChannelSection::Profile) {
      mesh::Mesh<3> mesh;
      try {
        mesh = mesh::gmsh_meshers().profile_die_mesh(spec.geometry, spec.solid.profile, spec.size,
                                                     spec.bearing_cell(), order);
      } catch (const mesh::GmshFailure& failure) {
        // The outline passed every check: what Gmsh still cannot build is a feature
        // finer than the cells asked of it (or OpenCASCADE's tolerance).
        const Case::KeyLocation where = location_of(case_, "geometry.profile", "mesh.size");
        throw InputError(
            where.file, where.line, "geometry.profile",
            fmt::format("Gmsh could not build or mesh the profile's die: {}", failure.what()),
            "make mesh.size (and mesh.bearing_size) smaller than the outline's "
            "thinnest leg, or simplify the outline");
      }
      if (cells.bubbles) return mesh::with_bubble_nodes(mesh);
      return mesh;
    }
    if (spec.dimension == 3) { // slab or square-die rectangle: io/case_validation_3d.cpp
      mesh::Mesh<3> mesh = mesh::gmsh_meshers().solid_channel_mesh(
          spec.geometry, spec.solid, spec.size, order, drawing, mesh::shape_of(spec.cell));
      if (cells.bubbles) return mesh::with_bubble_nodes(mesh);
      return mesh;
    }
    mesh::Mesh<2> mesh = mesh::gmsh_meshers().channel_mesh(
        spec.geometry, mesh::die_face_polyline(spec.geometry, spec.size), spec.size, order,
        mesh::shape_of(spec.cell));
    if (drawing) mesh::free_container_wall(mesh);
    if (cells.bubbles) return mesh::with_bubble_nodes(mesh);
    return mesh;
  }
  // A file's parts are the user's map: drawing maps the wall before the die to free_entry.
  const auto checked = [&](auto mesh) -> mesh::AnyMesh {
    check_jacobians(case_, spec, mesh);
    check_symmetry_planes(case_, spec, mesh);
    check_driven_part(case_, spec, mesh);
    return mesh;
  };
  const auto enriched = [&](auto read) {
    return cells.bubbles ? mesh::with_bubble_nodes(read) : read;
  };
  if (spec.source == mesh::MeshSource::Cad) return checked(enriched(read_cad_solid(case_, spec)));
  if (spec.dimension == 3) return checked(enriched(read_mesh_file<3>(case_, spec)));
  return checked(enriched(read_mesh_file<2>(case_, spec)));
#else
  const auto found = case_.key_locations.find("mesh.source");
  const Case::KeyLocation where =
      found == case_.key_locations.end() ? Case::KeyLocation{case_.source, 0} : found->second;
  throw InputError(where.file, where.line, "mesh.source",
                   "this formflow was built without Gmsh (FORMFLOW_WITH_GMSH=OFF)",
                   "use mesh.source = \"structured\", or rebuild with libgmsh-dev installed");
#endif
}

} // namespace formflow::io
