// SPDX-License-Identifier: MIT
// The unit square and the O-grid quarter disk as plane meshes of a cross-section.
#include "formflow/mesh/cross_section_mesh.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

namespace formflow::mesh {

namespace {

/// Builds a plane mesh from structured blocks whose shared edges produce
/// bit-identical lattice points (the blocks below evaluate the same expressions
/// there), so nodes are merged by exact coordinates.
class BlockMesh {
public:
  explicit BlockMesh(int order) { mesh_.order = order; }

  /// A block of `cells_a` × `cells_b` cells, lattice point (i, j) at
  /// `point(i / (order·cells_a), j / (order·cells_b))`, axis a first; `labels` of
  /// its four sides (local face numbering, std::nullopt: interior).
  void add_block(int cells_a, int cells_b, const std::function<Point<2>(Real, Real)>& point,
                 const std::array<std::optional<BoundaryLabel>, 4>& labels) {
    const int order = mesh_.order, n_side = order + 1;
    const int n_a = cells_a * order + 1, n_b = cells_b * order + 1;
    std::vector<Index> lattice(static_cast<std::size_t>(n_a) * n_b);
    for (int j = 0; j < n_b; ++j)
      for (int i = 0; i < n_a; ++i)
        lattice[j * n_a + i] =
            node_at(point(static_cast<Real>(i) / (n_a - 1), static_cast<Real>(j) / (n_b - 1)));
    for (int cb = 0; cb < cells_b; ++cb)
      for (int ca = 0; ca < cells_a; ++ca) {
        const Index cell = static_cast<Index>(cells_.size());
        std::vector<Index> local(n_side * n_side);
        for (int b = 0; b < n_side; ++b)
          for (int a = 0; a < n_side; ++a)
            local[b * n_side + a] = lattice[(cb * order + b) * n_a + ca * order + a];
        cells_.push_back(std::move(local));
        const std::array<bool, 4> on_side = {ca == 0, ca + 1 == cells_a, cb == 0,
                                             cb + 1 == cells_b};
        for (int face = 0; face < 4; ++face)
          if (on_side[face] && labels[face]) mesh_.facets.push_back({cell, face, *labels[face]});
      }
  }

  Mesh<2> finish() {
    const int per_cell = (mesh_.order + 1) * (mesh_.order + 1);
    mesh_.nodes.resize(2, static_cast<Index>(points_.size()));
    for (std::size_t n = 0; n < points_.size(); ++n) mesh_.nodes.col(n) = points_[n];
    mesh_.cells.resize(per_cell, static_cast<Index>(cells_.size()));
    for (std::size_t c = 0; c < cells_.size(); ++c)
      for (int a = 0; a < per_cell; ++a) mesh_.cells(a, c) = cells_[c][a];
    return std::move(mesh_);
  }

private:
  Index node_at(const Point<2>& point) {
    const auto [entry, inserted] =
        index_.try_emplace({point.x(), point.y()}, static_cast<Index>(points_.size()));
    if (inserted) points_.push_back(point);
    return entry->second;
  }

  Mesh<2> mesh_;
  std::vector<Point<2>> points_;
  std::vector<std::vector<Index>> cells_;
  std::map<std::pair<Real, Real>, Index> index_;
};

constexpr auto Symmetry = BoundaryLabel::Symmetry;
constexpr auto Outer = BoundaryLabel::Container;

} // namespace

Mesh<2> make_unit_square_section(int cells_y, int cells_z, int order) {
  FF_ASSERT(cells_y > 0 && cells_z > 0 && (order == 1 || order == 2), "cells and order");
  BlockMesh blocks(order);
  blocks.add_block(cells_y, cells_z, [](Real a, Real b) { return Point<2>(a, b); },
                   {Symmetry, Outer, Symmetry, Outer});
  return blocks.finish();
}

Mesh<2> make_quarter_disk_section(int radial_cells, int order) {
  FF_ASSERT(radial_cells > 0 && (order == 1 || order == 2), "cells and order");
  const int core = std::max(1, radial_cells / 2);
  const int ring = std::max(1, radial_cells - core);
  const Real side = static_cast<Real>(core) / (core + ring);
  // The curved block below the diagonal, axis a radial (≈ y), axis b tangential
  // (≈ z), so its cells are positively oriented in (y, z); the block above is its
  // mirror image (y ↔ z), evaluated as the same expression with the coordinates
  // swapped, so the two meet on the diagonal and on the axes bit for bit (the arc's
  // diagonal point has equal coordinates, cos 45° = sin 45° in floating point too).
  const auto lower = [side](Real radial, Real along) {
    const Real theta = along * std::numbers::pi / 4;
    const Point<2> on_arc = along == 1 ? Point<2>(std::sqrt(0.5), std::sqrt(0.5))
                                       : Point<2>(std::cos(theta), std::sin(theta));
    return ((1 - radial) * Point<2>(side, side * along) + radial * on_arc).eval();
  };
  BlockMesh blocks(order);
  blocks.add_block(core, core, [side](Real a, Real b) { return Point<2>(side * a, side * b); },
                   {Symmetry, std::nullopt, Symmetry, std::nullopt});
  blocks.add_block(ring, core, lower, {std::nullopt, Outer, Symmetry, std::nullopt});
  blocks.add_block(core, ring,
                   [&lower](Real along, Real radial) {
                     const Point<2> mirror = lower(radial, along);
                     return Point<2>(mirror.y(), mirror.x());
                   },
                   {Symmetry, std::nullopt, std::nullopt, Outer});
  Mesh<2> mesh = blocks.finish();
  const Index core_nodes = (core * order + 1) * (core * order + 1);
  FF_ASSERT(mesh.n_nodes() == core_nodes + Index(ring) * order * (core * order + 1) +
                                  Index(ring) * order * core * order,
            "the O-grid's blocks share their edges node for node");
  return mesh;
}

CoreRingSection make_core_ring_section(Real radius, Real half_y, Real half_z, int cells_y,
                                       int cells_z, int ring_cells, int order) {
  FF_ASSERT(cells_y > 0 && cells_z > 0 && ring_cells > 0 && (order == 1 || order == 2),
            "cells and order");
  FF_ASSERT(std::hypot(half_y, half_z) < radius, "the core's corner is inside the circle");
  const Real corner_angle = std::atan2(half_z, half_y);
  // The arc's point on the corner ray, and the blend; both blocks evaluate the
  // same expressions on the shared ray (η, corner) and on the core's sides (η = 0:
  // 1·side + 0·arc is the side bit for bit), so their nodes merge exactly.
  const Point<2> arc_corner = radius / std::hypot(half_y, half_z) * Point<2>(half_y, half_z);
  const auto blend = [](Real radial, const Point<2>& side, const Point<2>& arc) {
    return ((1 - radial) * side + radial * arc).eval();
  };
  const auto on_arc = [radius](Real angle) {
    return Point<2>(radius * std::cos(angle), radius * std::sin(angle));
  };
  // Below the corner ray: axis a radial (≈ y), axis b along the side y = half_y.
  const auto lower = [&](Real radial, Real along) {
    const Point<2> arc = along == 1   ? arc_corner
                         : along == 0 ? Point<2>(radius, 0.0)
                                      : on_arc(along * corner_angle);
    return blend(radial, Point<2>(half_y, half_z * along), arc);
  };
  // Above it: axis a along the side z = half_z (y from 0), axis b radial (≈ z);
  // the arc end at y = 0 is (0, radius) exactly (cos 90° is not 0 in floating point).
  const auto upper = [&](Real along, Real radial) {
    const Point<2> arc =
        along == 1   ? arc_corner
        : along == 0 ? Point<2>(0.0, radius)
                     : on_arc(std::numbers::pi / 2 - along * (std::numbers::pi / 2 - corner_angle));
    return blend(radial, Point<2>(half_y * along, half_z), arc);
  };
  constexpr auto Side = BoundaryLabel::FreeExit; // the core's outer sides, split off below
  BlockMesh blocks(order);
  blocks.add_block(cells_y, cells_z,
                   [=](Real a, Real b) { return Point<2>(half_y * a, half_z * b); },
                   {Symmetry, Side, Symmetry, Side});
  blocks.add_block(ring_cells, cells_z, lower, {std::nullopt, Outer, Symmetry, std::nullopt});
  blocks.add_block(cells_y, ring_cells, upper, {Symmetry, std::nullopt, std::nullopt, Outer});
  CoreRingSection section;
  section.mesh = blocks.finish();
  section.core_cells = Index(cells_y) * cells_z;
  std::vector<BoundaryFacet> boundary;
  for (const BoundaryFacet& facet : section.mesh.facets)
    (facet.label == Side ? section.core_sides : boundary).push_back(facet);
  section.mesh.facets = std::move(boundary);
  const Index core_nodes = Index(cells_y * order + 1) * (cells_z * order + 1);
  FF_ASSERT(section.mesh.n_nodes() ==
                core_nodes + Index(ring_cells) * order * (cells_y * order + cells_z * order + 1),
            "the O-grid's blocks share their edges node for node");
  return section;
}

} // namespace formflow::mesh
