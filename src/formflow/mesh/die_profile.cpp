// SPDX-License-Identifier: MIT
// Heights of wedge, arc and polyline die faces.
#include "formflow/mesh/die_profile.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace formflow::mesh {

DieProfile::DieProfile(const ChannelGeometry& geometry) : geometry_(geometry) {
  const Real drop = geometry.entry_half_height - geometry.exit_half_height;
  FF_ASSERT(drop > 0, "the die must reduce");
  switch (geometry.die) {
  case DieShape::Wedge:
    breakpoints_ = {0.0, drop / std::tan(geometry.die_angle * std::numbers::pi / 180.0)};
    break;
  case DieShape::Arc: {
    const Real radius = geometry.die_radius;
    FF_ASSERT(radius >= drop, "the arc must reach the entry height");
    breakpoints_ = {0.0, std::sqrt(radius * radius - (radius - drop) * (radius - drop))};
    break;
  }
  case DieShape::Polyline:
    FF_ASSERT(geometry.die_profile.size() >= 2, "a polyline needs two points");
    for (const auto& point : geometry.die_profile) breakpoints_.push_back(point[0]);
    break;
  case DieShape::Square: FF_ASSERT(false, "a square die has no face profile"); break;
  }
}

Real DieProfile::height(Real x) const {
  const Real entry = geometry_.entry_half_height, exit = geometry_.exit_half_height;
  x = std::clamp(x, 0.0, length());
  switch (geometry_.die) {
  case DieShape::Wedge: return entry - (entry - exit) * x / length();
  case DieShape::Arc: {
    // Centre (length, H_out + R): the arc meets the exit horizontally.
    const Real radius = geometry_.die_radius, from_exit = length() - x;
    return exit + radius - std::sqrt(std::max(0.0, radius * radius - from_exit * from_exit));
  }
  case DieShape::Polyline: {
    const auto& points = geometry_.die_profile;
    const auto upper = std::upper_bound(breakpoints_.begin() + 1, breakpoints_.end() - 1, x);
    const std::size_t k = static_cast<std::size_t>(upper - breakpoints_.begin()) - 1;
    const Real t = (x - points[k][0]) / (points[k + 1][0] - points[k][0]);
    return points[k][1] + t * (points[k + 1][1] - points[k][1]);
  }
  case DieShape::Square: break;
  }
  return entry;
}

} // namespace formflow::mesh
