// SPDX-License-Identifier: MIT
// Cell sizes that divide every length of a channel.
#include "formflow/mesh/fitting_sizes.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::mesh {

std::vector<Real> lengths_to_fit(const ChannelGeometry& geometry) {
  std::vector<Real> lengths = {geometry.container_length, geometry.entry_half_height,
                               geometry.exit_half_height, geometry.exit_length};
  if (geometry.land_length > 0) lengths.push_back(geometry.land_length);
  return lengths;
}

NearestFittingSizes nearest_fitting_sizes(std::span<const Real> lengths, Real size) {
  auto fits_all = [lengths](Real candidate) {
    return std::all_of(lengths.begin(), lengths.end(),
                       [candidate](Real length) { return cells_along(length, candidate) > 0; });
  };
  NearestFittingSizes out;
  constexpr int search = 10000;
  for (const Real length : lengths) {
    if (length / size > 1e7) continue; // no sensible mesh; also keeps the cell counts in int
    const int coarsest = std::max(1, static_cast<int>(std::ceil(length / size)));
    for (int n = coarsest; n < coarsest + search; ++n)
      if (fits_all(length / n)) {
        if (!out.smaller || length / n > out.smaller->size()) out.smaller = FittingSize{length, n};
        break;
      }
    // Both searches look at most `search` cell counts away: with ~1e7 cells
    // along a length an unbounded downward search took seconds per hint.
    const int finest = static_cast<int>(std::floor(length / size));
    for (int n = finest; n >= std::max(1, finest - search); --n)
      if (fits_all(length / n)) {
        if (!out.larger || length / n < out.larger->size()) out.larger = FittingSize{length, n};
        break;
      }
  }
  return out;
}

} // namespace formflow::mesh
