// SPDX-License-Identifier: MIT
// The outlines of polygons that tile a region edge to edge (a contour band's pieces).
#pragma once

#include "formflow/io/plot/canvas.hpp"

#include <span>
#include <vector>

namespace formflow::io::plot {

/// The rings that bound the union of `polygons`, polygons that meet edge to edge as
/// the cells of a mesh do: an edge two of them share (the same two points, in opposite
/// directions) cancels, and the edges left are chained into closed rings. Points that
/// agree to `snap` pixels are the same point (two cells sample their shared edge each
/// through its own shape functions: the points agree to round-off, not bit for bit).
/// Filled with the nonzero rule, the rings cover what the polygons cover when the
/// polygons are consistently oriented (a mesh's cells are); an edge that does not
/// cancel (a clipped piece's, or one whose copies differ by more than `snap`) stays in
/// a ring, which then only holds more points than it needs. Zero-length edges drop.
std::vector<std::vector<Pixel>> merged_outlines(std::span<const std::vector<Pixel>> polygons,
                                                double snap = 1.0 / 1024.0);

} // namespace formflow::io::plot
