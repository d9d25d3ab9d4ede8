// SPDX-License-Identifier: MIT
// Structured meshes of channels with wedge, arc and polyline dies and a die land.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"

namespace formflow::mesh {

/// The channel of `geometry` with any die shape: the square die is the
/// two-block channel of make_channel_mesh; the other shapes are one block
/// mapped onto x ∈ [0, L_c + L_die + L_land + L_e], 0 ≤ y ≤ h(x), with h the
/// die profile (mesh/die_profile.hpp). That map is the transfinite (Coons)
/// interpolation between the axis and the upper boundary along vertical cell
/// lines: rows are uniform fractions of the local half height, so every node
/// of the upper boundary (Q2 mid-side nodes too) lies on the die face.
/// Columns: L_c/size in the container, ⌈Δx/size⌉ on each straight piece of
/// the die face (its kinks are column lines), L_land/size on the land,
/// L_e/size in the exit; H_in/size rows.
/// Labels: as make_channel_mesh; the die face and the land are Die (Γ3).
/// Precondition: the case validation passed (sizes fit, the die reduces).
Mesh<2> make_die_channel_mesh(const ChannelGeometry& geometry, Real size, int order);

/// The number of cells make_die_channel_mesh(geometry, size, ·) makes, counted
/// without building the mesh, as a Real because it may exceed every index
/// type. For a size that does not fit the lengths (Gmsh's target size) it is
/// the count of a grid of that spacing: what a Gmsh mesh of that size has, roughly.
Real die_channel_cell_count(const ChannelGeometry& geometry, Real size);

/// Drawing has no container: the surface before the die is free (Γ2).
void free_container_wall(Mesh<2>& mesh);

/// x of the end of the die face (and start of the land), from the channel origin.
Real die_exit_position(const ChannelGeometry& geometry);

} // namespace formflow::mesh
