// SPDX-License-Identifier: MIT
// Where the mesh of a case comes from.
#pragma once

namespace formflow::mesh {

/// structured: the uniform square-cell generator (channel_mesh.hpp);
/// gmsh: the same channel geometry meshed by Gmsh with recombined quadrilaterals
/// (gmsh_channel.hpp); file: a user's .msh read through Gmsh (gmsh_mesh.hpp); cad: a
/// user's STEP/BREP solid meshed by Gmsh in tetrahedra (gmsh_cad_die.hpp).
enum class MeshSource { Structured, Gmsh, File, Cad };

} // namespace formflow::mesh
