// SPDX-License-Identifier: MIT
// The structured hexahedral mesh of a solid channel, by its section.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/mesh/solid_channel.hpp"

#include <vector>

namespace formflow::mesh {

/// The quarter (slab: the extruded half) model of `solid`'s section through the
/// die of `geometry`, cells of about `size` and polynomial `order`:
/// * slab: the plane channel extruded over the thickness, both z faces Symmetry
///   (mesh/extruded_mesh.hpp);
/// * rectangle, square die: mesh/rectangle_channel_mesh.hpp;
/// * rectangle, other dies: the unit square swept along the plane channel, the
///   half width following the half height linearly, w(h) = W_out + (W_in − W_out)
///   (h − H_out)/(H_in − H_out), so the die's y and z faces start and end together
///   (H_in/size rows, round(W_in/size) layers);
/// * round, square die: mesh/round_square_die_mesh.hpp (the O-grid around the
///   exit rectangle over the container, the rectangle alone over the exit);
/// * round, not a square die: the O-grid quarter disk (H_in/size cells along each
///   axis) swept along the plane channel: radius h(x), the revolved die face.
/// `drawing`: the container wall is free (Γ2), as free_container_wall in 2D.
/// Precondition: the case validation passed (io/case_validation_3d.cpp).
Mesh<3> make_solid_channel_mesh(const ChannelGeometry& geometry, const SolidChannel& solid,
                                Real size, int order, bool drawing);

/// The number of cells make_solid_channel_mesh makes, counted without building
/// it (as a Real: it may exceed every index type), for the memory check.
Real solid_channel_cell_count(const ChannelGeometry& geometry, const SolidChannel& solid,
                              Real size);

/// The lengths a structured solid mesh divides into cells of mesh.size: the plane
/// channel's (mesh::lengths_to_fit) and, for the rectangle, the container's half
/// width and, with the square die, the exit's; for the round section with the
/// square die, the exit's half width.
std::vector<Real> solid_lengths_to_fit(const ChannelGeometry& geometry, const SolidChannel& solid);

/// Whether a structured solid mesh of `size` can be made: the plane channel's
/// lengths and, for the rectangle, its half widths (both with the square die)
/// are multiples of it, and a round billet's square-die exit fits inside the
/// circle with half a cell to spare (mesh sequencing asks this of each coarse level).
bool solid_lengths_fit(const ChannelGeometry& geometry, const SolidChannel& solid, Real size);

} // namespace formflow::mesh
