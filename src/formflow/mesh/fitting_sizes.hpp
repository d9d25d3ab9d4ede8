// SPDX-License-Identifier: MIT
// Cell sizes that divide every length of a channel: the valid mesh.size values near a given one.
#pragma once

#include "formflow/mesh/channel_mesh.hpp"

#include <optional>
#include <span>
#include <vector>

namespace formflow::mesh {

/// The size `length` / `cells`, kept as the pair so that it can be shown as "10/32".
struct FittingSize {
  Real length = 0.0;
  int cells = 0;
  Real size() const { return length / cells; }
};

/// The nearest size at most and at least the asked one that divides every length
/// (cells_along > 0 for each); either may be missing when none is near.
struct NearestFittingSizes {
  std::optional<FittingSize> smaller;
  std::optional<FittingSize> larger;
};

/// The lengths of `geometry` a uniform grid divides: container and exit lengths,
/// entry and exit half heights, and the land when there is one.
std::vector<Real> lengths_to_fit(const ChannelGeometry& geometry);

/// Searches length/n for each of `lengths` (up to 10 000 values of n each).
NearestFittingSizes nearest_fitting_sizes(std::span<const Real> lengths, Real size);

} // namespace formflow::mesh
