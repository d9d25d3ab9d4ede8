// SPDX-License-Identifier: MIT
// Where the cells come from (mesh.source) and the keys each source reads: a mesh file, a
// die channel from CAD (mesh.source = "cad") and its defaults.
#pragma once

#include "formflow/io/case_validation_3d.hpp"

namespace formflow::io {

/// A CAD solid is meshed by Gmsh in tetrahedra with faceted curved walls: an unset
/// mesh.cell becomes "tetrahedron" and an unset contact.normals "nodes" (before
/// resolve_cell_defaults picks the element).
void resolve_cad_defaults(Case& case_, const std::function<bool(const std::string&)>& is_set);

/// Why the mesh source cannot serve the case: "file" without mesh.file; "cad" without
/// mesh.cad_file, not 3D, or with cells other than tetrahedra; mesh.file, mesh.cad_file or
/// mesh.boundaries set where the source reads none of them. An empty mesh.boundaries
/// with "cad" is left for the reading, whose message lists the solid's boundary surfaces
/// by tag and centre (how a user finds them). std::nullopt when fine.
std::optional<KeyRefusal> mesh_source_problem(const Case& case_);

} // namespace formflow::io
