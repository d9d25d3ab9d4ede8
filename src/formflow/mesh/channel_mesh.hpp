// SPDX-License-Identifier: MIT
// Structured quadrilateral mesh of the plane-strain extrusion channel (SPEC §4).
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// Half model of the die channel: a container [0, Lc] × [0, H_in] followed by
/// an exit [Lc, Lc + Le] × [0, H_out], symmetry plane y = 0. Lengths are
/// dimensionless (the benchmark: Lc = Le = 10, H_in = 10, H_out = 5).
struct ChannelGeometry {
  Real container_length = 10.0;
  Real entry_half_height = 10.0;
  Real exit_half_height = 5.0;
  Real exit_length = 10.0;
};

/// Number of cells that `size` fits into `length`, or -1 when it does not fit
/// within a relative 1e-9 (the generator only makes uniform square cells).
int cells_along(Real length, Real size);

/// Uniform square cells of side `size` and polynomial `order` (1 or 2).
/// Labels: rear x = 0; container y = H_in; die x = Lc, H_out < y < H_in;
/// free_exit y = H_out, x > Lc; front x = Lc + Le; symmetry y = 0.
/// Precondition: `size` fits every length (checked by the case validation).
Mesh<2> make_channel_mesh(const ChannelGeometry& geometry, Real size, int order);

}  // namespace formflow::mesh
