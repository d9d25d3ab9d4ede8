// SPDX-License-Identifier: MIT
// The mesh a case asks for: generated (structured or by Gmsh) or read from a .msh file.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/mesh/any_mesh.hpp"
#include "formflow/mesh/mesh_spec.hpp"

namespace formflow::io {

/// Makes or reads the mesh of `spec` (mesh.source) with cells of `case_`'s
/// element order, and checks that every cell has a positive Jacobian at every
/// Gauss point of the full rule. `spec` is `case_.mesh` or a variant of it (a
/// coarse level of mesh sequencing changes its size only); `case_` supplies
/// the element, the process (drawing frees the container wall) and the key
/// locations. Problems with mesh.file (missing, unreadable, wrong elements,
/// physical groups) are InputErrors naming the case file and line of the key
/// at fault. Gmsh and files give quadrilaterals; the structured source gives
/// hexahedra for geometry.dimension = 3 (the slab: the plane channel extruded,
/// mesh/extruded_mesh.hpp). The mesh says its dimension, and the run
/// dispatches on it (app/simulation.cpp).
mesh::AnyMesh load_mesh(const Case& case_, const mesh::MeshSpec& spec);

/// load_mesh(case_, case_.mesh).
inline mesh::AnyMesh load_mesh(const Case& case_) {
  return load_mesh(case_, case_.mesh);
}

} // namespace formflow::io
