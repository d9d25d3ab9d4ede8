// SPDX-License-Identifier: MIT
// The mesh a case asks for: generated (structured or by Gmsh) or read from a .msh file.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/mesh/mesh.hpp"

namespace formflow::io {

/// Makes or reads the mesh of `case_` (mesh.source) and checks that every cell
/// has a positive Jacobian at every Gauss point of the full rule. Problems with
/// mesh.file (missing, unreadable, wrong elements, physical groups) are
/// InputErrors naming the case file and line of the key at fault.
mesh::Mesh<2> load_mesh(const Case& case_);

} // namespace formflow::io
