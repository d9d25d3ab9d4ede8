// SPDX-License-Identifier: MIT
// The plane geometry of a profile's outline (mesh/profile_die.hpp).
#include "formflow/mesh/profile_die.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>

namespace formflow::mesh {

namespace {

using Point2 = std::array<Real, 2>;

Real cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

Real distance_to_segment(const Point2& a, const Point2& b, const Point2& p) {
  const Real dy = b[0] - a[0], dz = b[1] - a[1];
  const Real length2 = dy * dy + dz * dz;
  Real t = length2 > 0 ? ((p[0] - a[0]) * dy + (p[1] - a[1]) * dz) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dy, p[1] - a[1] - t * dz);
}

/// Whether segments ab and cd share a point, with orientations counted as zero below
/// `tolerance` (an area: length · the geometric tolerance), so that touching counts.
bool segments_meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                   Real tolerance) {
  const auto side = [tolerance](Real value) {
    return value > tolerance ? 1 : value < -tolerance ? -1 : 0;
  };
  const int d1 = side(cross(a, b, c)), d2 = side(cross(a, b, d));
  const int d3 = side(cross(c, d, a)), d4 = side(cross(c, d, b));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true; // a proper crossing
  const Real near = tolerance / std::max(std::hypot(b[0] - a[0], b[1] - a[1]), 1e-300);
  const Real near_cd = tolerance / std::max(std::hypot(d[0] - c[0], d[1] - c[1]), 1e-300);
  return distance_to_segment(a, b, c) <= near || distance_to_segment(a, b, d) <= near ||
         distance_to_segment(c, d, a) <= near_cd || distance_to_segment(c, d, b) <= near_cd;
}

std::string point_text(const Point2& p) {
  return fmt::format("({:.6g}, {:.6g})", p[0], p[1]);
}

} // namespace

Real ProfileDie::longest_bearing() const {
  return *std::max_element(bearing_length.begin(), bearing_length.end());
}

Real ProfileDie::shortest_bearing() const {
  return *std::min_element(bearing_length.begin(), bearing_length.end());
}

Real distance_to_edge(const ProfileDie& die, std::size_t edge, const Point2& point) {
  const std::size_t n = die.outline.size();
  return distance_to_segment(die.outline[edge], die.outline[(edge + 1) % n], point);
}

std::size_t nearest_edge(const ProfileDie& die, const Point2& point) {
  // Near a corner both edges' nearest point is the shared vertex: the distances tie over
  // a whole wedge. The edge whose line is farther then wins (the point lies beyond the
  // other edge's end, alongside this one), a rule that mirrors with the outline, so that
  // a symmetric profile splits its section symmetrically.
  const std::size_t n = die.outline.size();
  const auto line_distance = [&](std::size_t e) {
    const Point2& a = die.outline[e];
    const Point2& b = die.outline[(e + 1) % n];
    return std::abs(cross(a, b, point)) / std::hypot(b[0] - a[0], b[1] - a[1]);
  };
  // On the bisector of a corner even the lines tie; the edge more nearly along y then wins
  // (|Δy| is the same for an edge and its mirror in y = 0 or z = 0).
  const auto along_y = [&](std::size_t e) {
    const Point2& a = die.outline[e];
    const Point2& b = die.outline[(e + 1) % n];
    return std::abs(b[0] - a[0]) / std::hypot(b[0] - a[0], b[1] - a[1]);
  };
  std::size_t best = 0;
  Real best_distance = std::numeric_limits<Real>::infinity();
  const Real tie = 1e-12 * std::max(die.billet_radius, std::hypot(point[0], point[1]));
  for (std::size_t e = 0; e < n; ++e) {
    const Real distance = distance_to_edge(die, e, point);
    bool better = distance < best_distance - tie;
    if (!better && distance <= best_distance + tie) {
      const Real line = line_distance(e), best_line = line_distance(best);
      better =
          line > best_line + tie || (line >= best_line - tie && along_y(e) > along_y(best) + 1e-12);
    }
    if (better) {
      best = e;
      best_distance = std::min(distance, best_distance);
    }
  }
  return best;
}

std::vector<Point2> symmetry_images(const ProfileDie& die, const Point2& point) {
  std::vector<Point2> images = {point};
  if (die.symmetry != ProfileSymmetry::None) images.push_back({-point[0], point[1]});
  if (die.symmetry == ProfileSymmetry::YZ) {
    images.push_back({point[0], -point[1]});
    images.push_back({-point[0], -point[1]});
  }
  return images;
}

Real outline_area(const ProfileDie& die) {
  Real twice = 0.0;
  const std::size_t n = die.outline.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2& a = die.outline[k];
    const Point2& b = die.outline[(k + 1) % n];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * std::abs(twice);
}

Real profile_model_volume(const ProfileDie& die, Real container_length, Real exit_length) {
  const Real parts = die.symmetry == ProfileSymmetry::None ? 1.0
                     : die.symmetry == ProfileSymmetry::Y  ? 2.0
                                                           : 4.0;
  const Real billet = std::numbers::pi * die.billet_radius * die.billet_radius * container_length;
  return (billet + outline_area(die) * (die.longest_bearing() + exit_length)) / parts;
}

std::optional<std::string> profile_outline_problem(const ProfileDie& die) {
  const std::vector<Point2>& points = die.outline;
  const std::size_t n = points.size();
  if (n < 3)
    return fmt::format("the outline has {} point{}; a closed polygon needs at least 3", n,
                       n == 1 ? "" : "s");
  Real extent = die.billet_radius;
  for (const Point2& p : points) extent = std::max({extent, std::abs(p[0]), std::abs(p[1])});
  // Coordinates are kept to ~1e-12 relative through Gmsh's geometry; a gap below 1e-9 of
  // the outline's size is no gap a mesh could resolve.
  const Real tolerance = 1e-9 * extent;
  for (std::size_t k = 0; k < n; ++k) {
    const Point2& a = points[k];
    const Point2& b = points[(k + 1) % n];
    if (std::hypot(b[0] - a[0], b[1] - a[1]) <= tolerance)
      return fmt::format("points {} and {} are the same point {}{}", k, (k + 1) % n, point_text(a),
                         (k + 1) % n == 0 ? " (the outline closes itself: leave out the "
                                            "repeated first point)"
                                          : "");
  }
  for (std::size_t k = 0; k < n; ++k)
    if (std::hypot(points[k][0], points[k][1]) >= die.billet_radius - tolerance)
      return fmt::format("point {} {} is at radius {:.6g}, not inside the billet's radius {}", k,
                         point_text(points[k]), std::hypot(points[k][0], points[k][1]),
                         die.billet_radius);
  // Edges that meet other than at their shared end: O(n²) over at most a few thousand
  // points, well below the meshing time.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Point2& a = points[i];
      const Point2& b = points[(i + 1) % n];
      const Point2& c = points[j];
      const Point2& d = points[(j + 1) % n];
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Neighbours share one end; they overlap when the edge turns back on itself.
        const Point2& shared = j == i + 1 ? b : a;
        const Point2& p = j == i + 1 ? a : b;
        const Point2& q = j == i + 1 ? d : c;
        const Real turn = cross(shared, p, q);
        const Real dot =
            (p[0] - shared[0]) * (q[0] - shared[0]) + (p[1] - shared[1]) * (q[1] - shared[1]);
        if (std::abs(turn) <= tolerance * extent && dot > 0)
          return fmt::format("edges {} and {} fold back onto each other at point {} {}", i, j,
                             j == i + 1 ? j : i, point_text(shared));
        continue;
      }
      if (segments_meet(a, b, c, d, tolerance * extent))
        return fmt::format("edges {} ({} to {}) and {} ({} to {}) cross or touch: the outline "
                           "intersects itself",
                           i, point_text(a), point_text(b), j, point_text(c), point_text(d));
    }
  if (outline_area(die) <= tolerance * extent) return std::string("the outline encloses no area");
  if (die.symmetry == ProfileSymmetry::None) return std::nullopt;
  // Symmetric: every point's mirror lies on the outline (a vertex or on an edge).
  const auto on_outline = [&](const Point2& p) {
    for (std::size_t e = 0; e < n; ++e)
      if (distance_to_edge(die, e, p) <= 1e3 * tolerance) return true;
    return false;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const std::vector<Point2> images = symmetry_images(die, points[k]);
    for (std::size_t m = 1; m < images.size(); ++m)
      if (!on_outline(images[m]))
        return fmt::format("the outline is not symmetric about {}: the mirror {} of point {} "
                           "{} is not on it",
                           m == 1   ? "y = 0"
                           : m == 2 ? "z = 0"
                                    : "y = 0 and z = 0",
                           point_text(images[m]), k, point_text(points[k]));
  }
  return std::nullopt;
}

ProfileFileRead read_profile_csv(const std::string& text, std::size_t max_points) {
  ProfileFileRead read;
  std::istringstream lines(text);
  int number = 0;
  bool header_allowed = true;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::replace(line.begin(), line.end(), ';', ' ');
    std::istringstream fields(line);
    Point2 point{};
    std::string rest;
    const bool numbers = static_cast<bool>(fields >> point[0] >> point[1]);
    if (!numbers || (fields >> rest)) {
      // A header names its columns: it starts with a letter (a number never does).
      const std::size_t first = line.find_first_not_of(" \t");
      if (header_allowed && !numbers && std::isalpha(static_cast<unsigned char>(line[first]))) {
        header_allowed = false;
        continue;
      }
      read.problem = "expected two numbers `y, z`";
      read.line = number;
      return read;
    }
    header_allowed = false;
    if (!std::isfinite(point[0]) || !std::isfinite(point[1]) || std::abs(point[0]) > 1e6 ||
        std::abs(point[1]) > 1e6) {
      read.problem = "a coordinate is not finite or beyond 1e6";
      read.line = number;
      return read;
    }
    if (read.points.size() == max_points) {
      read.problem = fmt::format("more than {} points", max_points);
      read.line = number;
      return read;
    }
    read.points.push_back(point);
  }
  return read;
}

} // namespace formflow::mesh
