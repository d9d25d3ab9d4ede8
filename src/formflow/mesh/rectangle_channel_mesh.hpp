// SPDX-License-Identifier: MIT
// Quarter model of a rectangular bar through a square die: a box container and a
// narrower box exit.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/solid_channel.hpp"

namespace formflow::mesh {

/// Cubes of side `size` and polynomial `order` filling the container
/// [0, L_c] × [0, H_in] × [0, W_in] and the exit [L_c, L_c + L_e] × [0, H_out] ×
/// [0, W_out] (W the half widths of `solid`), one node lattice for both so the
/// exit's cells share the container's nodes on x = L_c. Labels: rear x = 0; front
/// x = L_c + L_e; symmetry y = 0 and z = 0; container y = H_in and z = W_in
/// (x < L_c); die: the L-shaped part of x = L_c outside the exit, and the first
/// L_land of the exit's outer faces; free_exit the rest of the exit's outer faces.
/// Precondition: `size` fits L_c, L_e, L_land, both half heights and both half
/// widths, H_out < H_in and W_out ≤ W_in (the case validation).
Mesh<3> make_rectangle_channel_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                    Real size, int order);

} // namespace formflow::mesh
