// SPDX-License-Identifier: MIT
// The die face of a wedge, arc or polyline die as a graph y = h(x).
#pragma once

#include "formflow/mesh/channel_mesh.hpp"

#include <vector>

namespace formflow::mesh {

/// The die face between the entry half height H_in (at the die entry x = 0,
/// i.e. x = L_c in the channel) and the exit half height H_out (at x = length()).
/// Wedge: straight, semi-angle α, length (H_in − H_out)/tan α. Arc: radius R,
/// tangent to the exit direction at the die exit (a smooth exit into the land),
/// length √(R² − (R − ΔH)²). Polyline: the given points.
/// Precondition: the geometry passed the case validation (io/case_cross_checks.cpp).
class DieProfile {
public:
  explicit DieProfile(const ChannelGeometry& geometry);

  /// x extent of the die face.
  Real length() const { return breakpoints_.back(); }
  /// Half height h(x) of the channel at x ∈ [0, length()] from the die entry.
  Real height(Real x) const;
  /// x of the ends and the kinks of the face, increasing: cell columns must
  /// start there so that the mesh follows the face exactly.
  const std::vector<Real>& breakpoints() const { return breakpoints_; }

private:
  ChannelGeometry geometry_;
  std::vector<Real> breakpoints_;
};

} // namespace formflow::mesh
