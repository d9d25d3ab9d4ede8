// SPDX-License-Identifier: MIT
// The inf-sup ladder of docs/mixed.md: β_h of each velocity/pressure pair on a
// small step channel (the benchmark's shape, scaled to 1 × 1 → ½) for h = 1/4, 1/8, ...
#pragma once

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/simplex_split.hpp"
#include "support/inf_sup.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace formflow::testing {

struct Pair {
  std::string name;
  int order;
  fem::PressureSpace space;
  bool filter;
  /// Triangles (the squares cut along a diagonal), with or without bubble nodes.
  bool triangles = false, bubbles = false;
};

inline const std::vector<Pair>& inf_sup_pairs() {
  static const std::vector<Pair> pairs = {
      {"Q2-P1disc", 2, fem::PressureSpace::P1disc, false},
      {"Q2-P0", 2, fem::PressureSpace::P0, false},
      {"Q2-Q1 (Taylor-Hood)", 2, fem::PressureSpace::Q1, false},
      {"Q2-Q1disc (= Q2, 2x2 rule)", 2, fem::PressureSpace::Q1disc, false},
      {"Q1-P0", 1, fem::PressureSpace::P0, false},
      {"Q1-P0 + 2x2 macro filter", 1, fem::PressureSpace::P0, true},
      {"Q1-Q1", 1, fem::PressureSpace::Q1, false},
      {"P2+-P1disc (triangles)", 2, fem::PressureSpace::P1disc, false, true, true},
      {"P2-P1 (Taylor-Hood, triangles)", 2, fem::PressureSpace::P1, false, true, false},
      {"P1b-P1 (MINI, triangles)", 1, fem::PressureSpace::P1, false, true, true},
      {"P2-P1disc (no bubbles, triangles)", 2, fem::PressureSpace::P1disc, false, true, false},
  };
  return pairs;
}

/// β_h per pair (rows) and cell size (columns); prints the markdown table.
inline std::vector<std::vector<testing::InfSupEstimate>>
inf_sup_table(const std::vector<int>& cells_per_unit) {
  const mesh::ChannelGeometry geometry{1.0, 1.0, 0.5, 1.0};
  std::vector<std::vector<testing::InfSupEstimate>> table;
  std::string header = "| pair |", rule = "|---|";
  for (int n : cells_per_unit) {
    header += " h = 1/" + std::to_string(n) + " |";
    rule += "---|";
  }
  std::printf("%s\n%s\n", header.c_str(), rule.c_str());
  for (const Pair& pair : inf_sup_pairs()) {
    std::vector<testing::InfSupEstimate> row;
    std::string line = "| " + pair.name + " |";
    for (int n : cells_per_unit) {
      mesh::Mesh<2> mesh = mesh::make_channel_mesh(geometry, 1.0 / n, pair.order);
      if (pair.triangles) mesh = mesh::split_into_triangles(mesh, pair.bubbles);
      row.push_back(testing::inf_sup_constant(mesh, pair.space, pair.filter));
      char cell[64];
      std::snprintf(cell, sizeof cell, " %.4f (%d null) |", row.back().beta,
                    row.back().n_null_modes);
      line += cell;
    }
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
    table.push_back(std::move(row));
  }
  return table;
}

} // namespace formflow::testing
