// SPDX-License-Identifier: MIT
// Structured quadrilateral mesh of the plane-strain extrusion channel (SPEC §4).
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <array>
#include <vector>

namespace formflow::mesh {

/// Shape of the die face between the entry height H_in and the exit height
/// H_out (mesh/die_profile.hpp): a step (the benchmark), a straight cone of
/// given semi-angle, a circular arc tangent to the exit, or a polyline.
enum class DieShape { Square, Wedge, Arc, Polyline };

/// Half model of the die channel: a container [0, Lc] × [0, H_in] followed by
/// an exit [Lc, Lc + Le] × [0, H_out], symmetry plane y = 0. Lengths are
/// dimensionless (the benchmark: Lc = Le = 10, H_in = 10, H_out = 5).
struct ChannelGeometry {
  Real container_length = 10.0;
  Real entry_half_height = 10.0;
  Real exit_half_height = 5.0;
  Real exit_length = 10.0;
  DieShape die = DieShape::Square;
  Real die_angle = 15.0;  ///< wedge semi-angle in degrees, 0 < α < 90
  Real die_radius = 10.0; ///< arc radius, ≥ H_in − H_out
  /// Polyline die face as (x, y) with x measured from the die entry x = L_c:
  /// starts at (0, H_in), ends at y = H_out, x increasing, y non-increasing.
  std::vector<std::array<Real, 2>> die_profile{};
  Real land_length = 0.0; ///< straight die land y = H_out after the die face (contact)
};

/// Number of cells that `size` fits into `length`, or -1 when it does not fit
/// within a relative 1e-9 (the generator only makes uniform square cells).
int cells_along(Real length, Real size);

/// Uniform square cells of side `size` and polynomial `order` (1 or 2).
/// Labels: rear x = 0; container y = H_in; die x = Lc, H_out < y < H_in;
/// free_exit y = H_out, x > Lc; front x = Lc + Le; symmetry y = 0.
/// Precondition: `size` fits every length (checked by the case validation).
Mesh<2> make_channel_mesh(const ChannelGeometry& geometry, Real size, int order);

} // namespace formflow::mesh
