// SPDX-License-Identifier: MIT
// A cross-section swept along a plane die channel: the rectangle and round sections
// with sloped or curved dies.
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <functional>

namespace formflow::mesh {

/// The solid channel whose meridian is the plane channel `channel` (a single
/// mapped block, mesh/die_channel_mesh.hpp: every column of nodes shares one x,
/// its top node is on the die face at the local half height h(x)) and whose
/// cross-section at x is `section` (a unit section in (y, z),
/// mesh/cross_section_mesh.hpp, of the same order) scaled by h(x) in y and by
/// `z_scale(h(x))` in z. Node (level, s) is x_level × section node s, numbered
/// level·n_section_nodes + s; a hexahedron's local axes are x, then the
/// section's two, so it is positively oriented when the section cell is.
/// Facets: x = 0 Rear and the far end Front (the plane channel's own labels),
/// the section's Symmetry edges stay Symmetry (the planes y = 0 and z = 0), its
/// outer edges take the label of the plane channel's upper facet in the same
/// column (container, die, free exit, free entry).
Mesh<3> sweep_section(const Mesh<2>& channel, const Mesh<2>& section,
                      const std::function<Real(Real)>& z_scale);

} // namespace formflow::mesh
