// SPDX-License-Identifier: MIT
// Sweeping a unit cross-section along the columns of a plane die channel.
#include "formflow/mesh/swept_mesh.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <map>
#include <vector>

namespace formflow::mesh {

namespace {

/// The channel's node columns: their x (increasing) and their top height h(x).
struct Levels {
  std::vector<Real> x, height;
};

Levels node_levels(const Mesh<2>& channel) {
  // A mapped channel's column shares one x computed once (bit-identical), so an
  // exact key groups it.
  std::map<Real, Real> top;
  for (Index n = 0; n < channel.n_nodes(); ++n) {
    auto [entry, inserted] = top.try_emplace(channel.nodes(0, n), channel.nodes(1, n));
    entry->second = std::max(entry->second, channel.nodes(1, n));
  }
  Levels levels;
  for (const auto& [x, height] : top) {
    levels.x.push_back(x);
    levels.height.push_back(height);
  }
  return levels;
}

/// The label of each column's upper face, from the channel's facets that are
/// neither an end nor the symmetry line.
std::vector<BoundaryLabel> column_labels(const Mesh<2>& channel, const Levels& levels) {
  const int order = channel.order;
  const int n_columns = static_cast<int>(levels.x.size() - 1) / order;
  std::vector<BoundaryLabel> labels(n_columns, BoundaryLabel::FreeExit);
  std::vector<bool> seen(n_columns, false);
  for (const BoundaryFacet& facet : channel.facets) {
    if (facet.label == BoundaryLabel::Rear || facet.label == BoundaryLabel::Front ||
        facet.label == BoundaryLabel::Symmetry)
      continue;
    const auto face = channel.face_nodes(facet.local_face);
    const Real middle = 0.5 * (channel.nodes(0, channel.cells(face.front(), facet.cell)) +
                               channel.nodes(0, channel.cells(face.back(), facet.cell)));
    const auto above = std::upper_bound(levels.x.begin(), levels.x.end(), middle);
    const int column = static_cast<int>(above - levels.x.begin() - 1) / order;
    FF_ASSERT(column >= 0 && column < n_columns, "an upper facet lies over a column");
    labels[column] = facet.label;
    seen[column] = true;
  }
  FF_ASSERT(std::all_of(seen.begin(), seen.end(), [](bool s) { return s; }),
            "every column has an upper facet: the channel is one mapped block");
  return labels;
}

} // namespace

Mesh<3> sweep_section(const Mesh<2>& channel, const Mesh<2>& section,
                      const std::function<Real(Real)>& z_scale) {
  FF_ASSERT(channel.order == section.order, "the channel and the section have one order");
  const int order = channel.order, n_side = order + 1;
  const Levels levels = node_levels(channel);
  const std::vector<BoundaryLabel> top = column_labels(channel, levels);
  const Index n_levels = static_cast<Index>(levels.x.size());
  const Index n_section = section.n_nodes(), n_section_cells = section.n_cells();
  const int n_columns = static_cast<int>(top.size());

  Mesh<3> mesh;
  mesh.order = order;
  mesh.nodes.resize(3, n_levels * n_section);
  for (Index level = 0; level < n_levels; ++level) {
    const Real height = levels.height[level], width = z_scale(height);
    for (Index s = 0; s < n_section; ++s)
      mesh.nodes.col(level * n_section + s) << levels.x[level], height * section.nodes(0, s),
          width * section.nodes(1, s);
  }

  mesh.cells.resize(n_side * n_side * n_side, Index(n_columns) * n_section_cells);
  for (int column = 0; column < n_columns; ++column)
    for (Index s = 0; s < n_section_cells; ++s) {
      const Index cell = column * n_section_cells + s;
      // Hexahedron node (a, b, c) = level column·order + a of section node (b, c).
      for (int in_section = 0; in_section < n_side * n_side; ++in_section)
        for (int a = 0; a < n_side; ++a)
          mesh.cells(in_section * n_side + a, cell) =
              (Index(column) * order + a) * n_section + section.cells(in_section, s);
      if (column == 0) mesh.facets.push_back({cell, 0, BoundaryLabel::Rear});
      if (column + 1 == n_columns) mesh.facets.push_back({cell, 1, BoundaryLabel::Front});
    }
  // The section's faces 0–3 are its (y, z) sides, the hexahedron's faces 2–5.
  for (int column = 0; column < n_columns; ++column)
    for (const BoundaryFacet& facet : section.facets)
      mesh.facets.push_back(
          {column * n_section_cells + facet.cell, facet.local_face + 2,
           facet.label == BoundaryLabel::Symmetry ? BoundaryLabel::Symmetry : top[column]});
  return mesh;
}

} // namespace formflow::mesh
