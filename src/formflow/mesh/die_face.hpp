// SPDX-License-Identifier: MIT
// The die face as a polyline: the geometry the Gmsh channel meshers are built from.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"

#include <vector>

namespace formflow::mesh {

/// The die face of the square die: from the top of the die (L_c, H_in) straight
/// down to the start of the exit (L_c, H_out).
std::vector<Point<2>> square_die_face(const ChannelGeometry& geometry);

/// The die face of any geometry.die as a polyline for build_channel_model, the
/// die land (if any) appended: square, wedge and polyline dies exactly; the
/// arc by chords of at most size/2 (straight cell faces keep the penalty
/// contact free of the curved-face trouble described in docs/gmsh-meshes.md).
std::vector<Point<2>> die_face_polyline(const ChannelGeometry& geometry, Real size);

} // namespace formflow::mesh
