// SPDX-License-Identifier: MIT
// Quarter model of a round billet through a square (flat) die into a rectangular
// product: an O-grid container whose core continues alone downstream.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/solid_channel.hpp"

namespace formflow::mesh {

/// Radial cells of the ring between the exit rectangle and the container's
/// circle: the widest gap (on the axis of the shorter half side) in cells of
/// about `size`, at least one.
int round_square_ring_cells(const ChannelGeometry& geometry, const SolidChannel& solid, Real size);

/// Whether the exit's corner (H_out, W_out) is inside the container's circle of
/// radius H_in with a margin of half a cell: the ring's cells on the corner ray
/// are then at least about size/2 / ring_cells thick.
bool round_square_exit_fits(const ChannelGeometry& geometry, const SolidChannel& solid, Real size);

/// The cross-section of mesh/cross_section_mesh.hpp make_core_ring_section with
/// radius H_in (geometry.entry_half_height) and core [0, H_out] × [0, W_out]
/// (geometry.exit_half_height, solid.exit_half_width) in cells of `size`,
/// extruded along x: the whole section over the container [0, L_c], the core
/// alone over the exit [L_c, L_c + L_e], sharing the nodes of x = L_c. Labels:
/// rear x = 0; front x = L_c + L_e; symmetry y = 0 and z = 0; container the
/// cylinder y² + z² = H_in² (x < L_c); die: the ring's faces on x = L_c (the
/// flat die face, outward normal +x, as the rectangle's square die) and the first
/// L_land of the core's outer faces; free_exit the rest of them.
/// Precondition: `size` fits L_c, L_e, L_land, H_out and W_out, and
/// round_square_exit_fits (the case validation).
Mesh<3> make_round_square_die_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                   Real size, int order);

/// The number of cells make_round_square_die_mesh makes (as a Real, for the
/// memory check, without building the mesh).
Real round_square_die_cell_count(const ChannelGeometry& geometry, const SolidChannel& solid,
                                 Real size);

} // namespace formflow::mesh
