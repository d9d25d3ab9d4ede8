// SPDX-License-Identifier: MIT
// The outlines of polygons that tile a region edge to edge, by cancelling shared edges.
//
// Why not a polygon-clipping library (Boost.Geometry's union_, Clipper): a band's
// pieces meet on whole shared edges, so their union is a question of topology, not of
// intersections — cancelling the edges two pieces share is a hash lookup per edge, and
// a general union of thousands of polygons costs more than the drawing it saves.
#include "formflow/io/plot/polygon_outlines.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace formflow::io::plot {

namespace {

/// A point's place on the snapping grid.
struct GridKey {
  std::int64_t x, y;
  bool operator==(const GridKey&) const = default;
};

struct GridKeyHash {
  std::size_t operator()(const GridKey& key) const {
    // Unsigned: a signed product would overflow.
    return static_cast<std::size_t>(static_cast<std::uint64_t>(key.x) * 0x9E3779B97F4A7C15ULL ^
                                    static_cast<std::uint64_t>(key.y));
  }
};

/// A directed edge between two numbered points.
struct Edge {
  std::int32_t from, to;
  bool operator==(const Edge&) const = default;
};

struct EdgeHash {
  std::size_t operator()(const Edge& edge) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(edge.from) << 32) ^
                                    static_cast<std::uint32_t>(edge.to));
  }
};

} // namespace

std::vector<std::vector<Pixel>> merged_outlines(std::span<const std::vector<Pixel>> polygons,
                                                double snap) {
  // Number the points (the first of those that snap together is kept).
  std::unordered_map<GridKey, std::int32_t, GridKeyHash> numbers;
  std::vector<Pixel> points;
  const auto number_of = [&](const Pixel& at) {
    const GridKey key{std::llround(at[0] / snap), std::llround(at[1] / snap)};
    const auto [found, added] = numbers.try_emplace(key, static_cast<std::int32_t>(points.size()));
    if (added) points.push_back(at);
    return found->second;
  };
  // Each edge's count: +1 per copy in its direction; a copy in the opposite direction
  // cancels one instead. Every polygon is closed, and a cancelled pair takes one edge
  // in and one out of both its points, so the edges left have as many in as out at
  // every point: a walk along them can only end where it began.
  std::unordered_map<Edge, int, EdgeHash> count;
  std::size_t n_edges = 0;
  for (const std::vector<Pixel>& polygon : polygons) {
    if (polygon.size() < 3) continue;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const std::int32_t from = number_of(polygon[i]);
      const std::int32_t to = number_of(polygon[(i + 1) % polygon.size()]);
      if (from == to) continue;
      if (const auto reverse = count.find({to, from}); reverse != count.end()) {
        if (--reverse->second == 0) count.erase(reverse);
        --n_edges;
        continue;
      }
      ++count[{from, to}];
      ++n_edges;
    }
  }
  // The edges out of each point, then the rings.
  std::vector<std::int32_t> first_out(points.size() + 1, 0);
  for (const auto& [edge, copies] : count) first_out[edge.from + 1] += copies;
  for (std::size_t p = 0; p < points.size(); ++p) first_out[p + 1] += first_out[p];
  std::vector<std::int32_t> target(n_edges);
  std::vector<std::int32_t> fill(first_out.begin(), first_out.end() - 1);
  for (const auto& [edge, copies] : count)
    for (int copy = 0; copy < copies; ++copy) target[fill[edge.from]++] = edge.to;
  std::vector<std::int32_t> next_out(first_out.begin(), first_out.end() - 1); // unused edges
  std::vector<std::vector<Pixel>> rings;
  for (std::size_t start = 0; start < points.size(); ++start) {
    while (next_out[start] < first_out[start + 1]) {
      std::vector<Pixel> ring;
      auto at = static_cast<std::int32_t>(start);
      // Each step uses up one edge, so the walk ends after at most n_edges steps.
      while (next_out[at] < first_out[at + 1]) {
        ring.push_back(points[at]);
        at = target[next_out[at]++];
        if (at == static_cast<std::int32_t>(start)) break;
      }
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
  }
  return rings;
}

} // namespace formflow::io::plot
