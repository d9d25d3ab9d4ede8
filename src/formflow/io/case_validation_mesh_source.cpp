// SPDX-License-Identifier: MIT
// Mesh sources: the keys they read, CAD defaults (io/case_validation_mesh_source.hpp).
#include "formflow/io/case_validation_mesh_source.hpp"

#include "formflow/io/case_keys.hpp"

#include <array>

namespace formflow::io {

void resolve_cad_defaults(Case& case_, const std::function<bool(const std::string&)>& is_set) {
  if (case_.mesh.source != mesh::MeshSource::Cad || case_.mesh.dimension != 3) return;
  if (!is_set("mesh.cell")) case_.mesh.cell = mesh::CellKind::Tetrahedron;
  // A CAD die is curved and its tetrahedra's faces are flat: each face's own normal
  // penalised at its Gauss points pins the nodes the facets share (on a cone, in every
  // direction: the conical die's load at h = 0.5 is 134 with face normals, 3.35 with
  // nodal ones); one mean normal per node lets the metal slide along the wall.
  if (!is_set("contact.normals")) case_.contact.normals = assembly::ContactNormals::Nodes;
}

std::optional<KeyRefusal> mesh_source_problem(const Case& case_) {
  const bool from_file = case_.mesh.source == mesh::MeshSource::File;
  const bool from_cad = case_.mesh.source == mesh::MeshSource::Cad;
  if (from_file && case_.mesh.file.empty())
    return KeyRefusal{{"mesh.source"},
                      "value \"file\" needs mesh.file, which is not set",
                      "e.g. file = \"meshes/die.msh\" in [mesh]"};
  if (from_cad && case_.mesh.cad_file.empty())
    return KeyRefusal{{"mesh.source"},
                      "value \"cad\" needs mesh.cad_file, which is not set",
                      "e.g. cad_file = \"die.step\" in [mesh]"};
  if (from_cad && case_.mesh.dimension != 3)
    return KeyRefusal{{"mesh.source", "geometry.dimension"},
                      "a CAD solid is three-dimensional",
                      "set geometry.dimension = 3"};
  if (from_cad && case_.mesh.cell != mesh::CellKind::Tetrahedron)
    return KeyRefusal{{"mesh.cell", "mesh.source"},
                      "Gmsh meshes a CAD solid in tetrahedra (no hexahedral mesher serves "
                      "any solid)",
                      "leave mesh.cell out (or set it to \"tetrahedron\")"};
  struct Reader {
    const char* key;
    bool set, read;
    const char* source;
  };
  const std::array<Reader, 3> readers = {
      {{"mesh.file", !case_.mesh.file.empty(), from_file, "\"file\""},
       {"mesh.cad_file", !case_.mesh.cad_file.empty(), from_cad, "\"cad\""},
       {"mesh.boundaries", !case_.mesh.boundaries.empty(), from_file || from_cad,
        "\"file\" or \"cad\""}}};
  for (const Reader& reader : readers)
    if (reader.set && !reader.read)
      return KeyRefusal{
          {reader.key},
          "is set but mesh.source = " + format_key_value(find_case_key("mesh.source")->get(case_)) +
              " does not read it",
          std::string("set mesh.source = ") + reader.source + " to use it"};
  return std::nullopt;
}

} // namespace formflow::io
