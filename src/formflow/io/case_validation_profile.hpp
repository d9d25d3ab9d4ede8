// SPDX-License-Identifier: MIT
// A profile through a flat die (geometry.section = "profile"): its defaults, its outline
// file, and what such a case must hold before Gmsh builds it.
#pragma once

#include "formflow/io/case_validation_3d.hpp"

namespace formflow::io {

/// A profile is built by Gmsh in tetrahedra: an unset mesh.source becomes "gmsh" and an
/// unset mesh.cell "tetrahedron" (before resolve_cell_defaults picks the element), an
/// unset contact.normals "nodes" (the billet's wall is faceted).
void resolve_profile_defaults(Case& case_, const std::function<bool(const std::string&)>& is_set);

/// Reads geometry.profile_file (set at `file`:`line`; a relative path from that file's
/// directory) into mesh.solid.profile.outline. Throws InputError naming the key, and the
/// CSV's own line for a line that is not `y, z`, without quoting a file that is not one.
/// Also refuses an outline given twice (geometry.profile set as well).
void read_profile_file(Case& case_, const std::string& file, int line);

/// Why a profile case cannot be built: not 3D, a source or cell other than Gmsh's
/// tetrahedra, no outline, an outline that is not a simple polygon inside the
/// billet or not symmetric as geometry.profile_symmetry says, a bearing list whose length
/// is not the edge count, a bearing shorter than its cell, drawing (the ram pushes a
/// billet), or a key of the plane channel's die set in vain. std::nullopt when fine.
std::optional<KeyRefusal>
profile_case_problem(const Case& case_, const std::function<bool(const std::string&)>& is_set);

} // namespace formflow::io
