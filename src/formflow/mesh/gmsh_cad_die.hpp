// SPDX-License-Identifier: MIT
// A user's die channel from CAD (mesh.source = "cad"): the solid of a STEP or BREP file,
// read by OpenCASCADE and meshed by Gmsh in tetrahedra.
#pragma once

#include "formflow/mesh/cad_file.hpp"
#include "formflow/mesh/gmsh_mesh.hpp"
#include "formflow/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace formflow::mesh {

/// The solids of `path` (checked by check_cad_file as `format`; several solids are
/// fragmented into one conforming model), meshed in tetrahedra of `order` (straight
/// edges) and target size `size`. `boundaries` maps each boundary surface, by its tag in
/// the imported model as text ("1", "2", ...; Gmsh's GUI shows them), to a part.
/// Throws MeshFileError: no solid (Subject::File); a mapped tag that is no boundary
/// surface (Subject::Group, the tag as group); boundary surfaces left unmapped
/// (Subject::Boundaries, listing them with their centres so that they can be found).
/// A failure of OpenCASCADE or Gmsh itself propagates as GmshFailure.
Mesh<3> make_gmsh_cad_mesh(const std::string& path, CadFormat format,
                           const std::vector<PhysicalBoundary>& boundaries, Real size, int order);

} // namespace formflow::mesh
