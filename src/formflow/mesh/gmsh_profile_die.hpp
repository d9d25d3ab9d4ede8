// SPDX-License-Identifier: MIT
// A profile through a flat die (geometry.section = "profile") built with Gmsh's
// OpenCASCADE kernel and meshed in tetrahedra.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/mesh/profile_die.hpp"

namespace formflow::mesh {

/// The solid of `die` (mesh/profile_die.hpp; x the extrusion direction): the billet
/// cylinder x ∈ [0, L_c] of radius R, the opening's prism from the die face x = L_c to
/// x_end = L_c + max bearing + L_e, cut in x at every distinct bearing length so that
/// each edge's bearing ends on a mesh line; reduced to y ≥ 0 (and z ≥ 0) by the
/// symmetry; fragmented into one conforming model. Parts: rear x = 0, container (the
/// billet's wall), die (the flat face x = L_c around the opening and each edge's
/// bearing wall up to L_c + bearing(e)), free_exit (the extrudate's wall after it),
/// front x = x_end, symmetry (y = 0, z = 0 as the symmetry has them).
/// Tetrahedra of `order` (tetra-4, or tetra-10 with straight edges: the billet's wall
/// is faceted, so that no curved edge can fold a cell), size `size`, graded down to
/// `bearing_size` within a bearing_size of the bearing walls and of the die opening.
/// Precondition: profile_outline_problem(die) is empty (the case validation).
Mesh<3> make_gmsh_profile_die_mesh(const ChannelGeometry& geometry, const ProfileDie& die,
                                   Real size, Real bearing_size, int order);

} // namespace formflow::mesh
