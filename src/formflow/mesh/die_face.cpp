// SPDX-License-Identifier: MIT
// The die face as a polyline (no Gmsh here: the adaptive loop asks for it too).
#include "formflow/mesh/die_face.hpp"

#include "formflow/mesh/die_profile.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::mesh {

std::vector<Point<2>> square_die_face(const ChannelGeometry& geometry) {
  return {Point<2>(geometry.container_length, geometry.entry_half_height),
          Point<2>(geometry.container_length, geometry.exit_half_height)};
}

std::vector<Point<2>> die_face_polyline(const ChannelGeometry& geometry, Real size) {
  std::vector<Point<2>> face;
  if (geometry.die == DieShape::Square) {
    face = square_die_face(geometry);
  } else {
    const DieProfile profile(geometry);
    const std::vector<Real>& breaks = profile.breakpoints();
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
      const Real span = breaks[k + 1] - breaks[k];
      const int pieces = geometry.die == DieShape::Arc
                             ? std::max(1, static_cast<int>(std::ceil(2.0 * span / size)))
                             : 1;
      for (int piece = 0; piece < pieces; ++piece) {
        const Real x = breaks[k] + span * piece / pieces;
        face.emplace_back(geometry.container_length + x, profile.height(x));
      }
    }
    face.emplace_back(geometry.container_length + profile.length(), geometry.exit_half_height);
  }
  if (geometry.land_length > 0)
    face.emplace_back(face.back().x() + geometry.land_length, geometry.exit_half_height);
  return face;
}

} // namespace formflow::mesh
