// SPDX-License-Identifier: MIT
// Case keys of the [mesh] section (Where the cells come from): rows of the table in
// io/case_keys.cpp.
#include "formflow/io/keys/key_spec.hpp"

namespace formflow::io::keys {

namespace {

KeySpec mesh_file_key() {
  KeySpec spec("mesh.file", KeyType::Text, std::string());
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh.file = std::get<std::string>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.mesh.file; };
  return spec.constraint("required when mesh.source = \"file\"; only then")
      .doc("the Gmsh mesh (.msh 4.1 or 2.2, ASCII or binary) of quad-4 (Q1) or quad-9 (Q2) "
           "cells, or with geometry.dimension = 3 of hexa-8 (Q1) or hexa-27 (Q2) cells; a "
           "relative path is taken from the case file's directory");
}

KeySpec cad_file_key() {
  KeySpec spec("mesh.cad_file", KeyType::Text, std::string());
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh.cad_file = std::get<std::string>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.mesh.cad_file; };
  return spec.constraint("required when mesh.source = \"cad\"; only then")
      .doc("the die channel's material region as a closed solid, STEP (.step, .stp) or BREP "
           "(.brep), read by OpenCASCADE only; its boundary surfaces are mapped to parts by "
           "tag in mesh.boundaries; a relative path is taken from the case file's directory "
           "(docs/cad.md)");
}

KeySpec mesh_boundaries_key() {
  KeySpec spec("mesh.boundaries", KeyType::NameMap, NameMap{});
  for (int k = 0; k < mesh::n_boundary_labels; ++k)
    spec.key.choices.push_back(mesh::label_name(static_cast<mesh::BoundaryLabel>(k)));
  spec.key.set = [](Case& case_, const KeyValue& value) {
    case_.mesh.boundaries = std::get<NameMap>(value);
  };
  spec.key.get = [](const Case& case_) -> KeyValue { return case_.mesh.boundaries; };
  return spec.constraint("only with mesh.source = \"file\" or \"cad\" (required there)")
      .doc("physical curve (3D: surface) name in mesh.file → boundary part, as a table "
           "`[mesh.boundaries]` "
           "with lines `ram = \"rear\"`; several names may share a part; every boundary "
           "facet needs one; {} = the physical names are the part names; with mesh.cad_file "
           "the keys are surface tags (`\"3\" = \"die\"`)");
}

} // namespace

std::vector<CaseKey> mesh_keys() {
  return {
      enum_key(
          "mesh.cell", "quadrilateral",
          {{"quadrilateral", mesh::CellKind::Quadrilateral},
           {"triangle", mesh::CellKind::Triangle},
           {"hexahedron", mesh::CellKind::Hexahedron},
           {"tetrahedron", mesh::CellKind::Tetrahedron}},
          [](auto& c) -> auto& { return c.mesh.cell; })
          .constraint("quadrilateral or triangle with geometry.dimension = 2, hexahedron or "
                      "tetrahedron with 3; unset: the quadrilateral or hexahedron")
          .doc("cell shape: quadrilaterals/hexahedra (elements Q1, Q2) or triangles/tetrahedra "
               "(elements P1b, P2; the mixed formulation, docs/simplices.md)"),
      enum_key(
          "mesh.element", "Q2",
          {{"Q1", fem::ElementKind::Q1},
           {"Q2", fem::ElementKind::Q2},
           {"P1b", fem::ElementKind::P1b},
           {"P2", fem::ElementKind::P2}},
          [](auto& c) -> auto& { return c.element; })
          .constraint("Q1 or Q2 on quadrilaterals and hexahedra, P1b or P2 on triangles and "
                      "tetrahedra; unset: Q2, or P2 on simplices")
          .doc("velocity element: Q1 (4-node bilinear), Q2 (9-node biquadratic); on simplices "
               "P1b (MINI: linear and a cell bubble, continuous P1 pressure) or P2 "
               "(quadratic; with a discontinuous pressure enriched by bubbles, P2+)"),
      real_key(
          "mesh.size", 1.0, [](auto& c) -> auto& { return c.mesh.size; })
          .within(1e-6, 1e6)
          .why(length_range)
          .constraint("divides every geometry length when mesh.source = \"structured\"; the "
                      "mesh's estimated memory fits in this machine's (docs/benchmarks.md)")
          .unit("length")
          .doc("side of the uniform square cells (mesh I: 10/6, mesh II: 1); the target "
               "element size for mesh.source = \"gmsh\"; unused for \"file\""),
      real_key(
          "mesh.bearing_size", 0.0, [](auto& c) -> auto& { return c.mesh.bearing_size; })
          .zero_or_at_least(1e-6)
          .at_most(1e6)
          .why(length_range)
          .constraint("geometry.section = \"profile\"; ≤ mesh.size")
          .unit("length")
          .doc("profile: the cell size along the bearing walls, growing to mesh.size at "
               "4 mesh.size from them; 0 = mesh.size / 2"),
      enum_key(
          "mesh.source", "structured",
          {{"structured", mesh::MeshSource::Structured},
           {"gmsh", mesh::MeshSource::Gmsh},
           {"file", mesh::MeshSource::File},
           {"cad", mesh::MeshSource::Cad}},
          [](auto& c) -> auto& { return c.mesh.source; })
          .doc("structured: uniform square cells; gmsh: the same geometry meshed by Gmsh with "
               "recombined quadrilaterals of size mesh.size (in 3D: extruded into hexahedra); "
               "file: the mesh in mesh.file (quadrilaterals, or hexahedra in 3D); "
               "geometry.section = \"profile\" is always built by Gmsh (unset: gmsh); cad: "
               "the solid of mesh.cad_file meshed by Gmsh in tetrahedra (3D)"),
      mesh_file_key(),
      cad_file_key(),
      mesh_boundaries_key(),
  };
}

} // namespace formflow::io::keys
