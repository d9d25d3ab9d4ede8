// SPDX-License-Identifier: MIT
// The physical groups of a Gmsh solid model that solid_mesh_from_gmsh_model reads: one
// surface group per boundary part, named like the part, and the volumes as "domain".
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <map>
#include <vector>

namespace formflow::mesh {

/// The surfaces of the current (synchronised) model on its boundary: those bounding one
/// volume only (a surface between two volumes is inside).
std::vector<int> boundary_surfaces();

/// Adds a physical surface per part of `parts` (label → surface tags), named like the
/// part, and one physical volume "domain" of every volume.
void add_solid_groups(const std::map<BoundaryLabel, std::vector<int>>& parts);

} // namespace formflow::mesh
