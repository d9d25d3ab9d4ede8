// SPDX-License-Identifier: MIT
// The channel remeshed by Gmsh with a cell size that varies: the meshes of adaptivity.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/mesh.hpp"

#include <vector>

namespace formflow::mesh {

/// The channel of `geometry` with `die_face` (as build_channel_model takes it),
/// meshed by Gmsh with recombined quadrilaterals of `order` whose size follows
/// `node_sizes`, one target size per node of `background` (any plane mesh of the
/// same channel, e.g. the previous cycle's), interpolated bilinearly on the
/// background's corner nodes (a Gmsh PostView background field). The boundary
/// points' own sizes and the boundary's extension are switched off, so the field
/// alone decides. Sizes must be positive and finite.
Mesh<2> make_sized_gmsh_channel_mesh(const ChannelGeometry& geometry,
                                     const std::vector<Point<2>>& die_face,
                                     const Mesh<2>& background, const VectorX& node_sizes,
                                     int order);

} // namespace formflow::mesh
