// SPDX-License-Identifier: MIT
// Triangles from a quadrilateral mesh, and the bubble nodes of P1b / P2+.
#include "formflow/mesh/simplex_split.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace formflow::mesh {

namespace {

/// Local nodes of the two triangles of a quadrilateral, in triangle order (vertices, then
/// the midpoints of edges (0,1), (1,2), (2,0)), as lexicographic local nodes of the
/// quadrilateral: A = (0, 1, 3), B = (0, 3, 2) in Q1 vertex numbering.
constexpr std::array<std::array<int, 3>, 2> q1_triangles{{{0, 1, 3}, {0, 3, 2}}};
constexpr std::array<std::array<int, 6>, 2> q2_triangles{{{0, 2, 8, 1, 5, 4}, {0, 8, 6, 4, 7, 3}}};

/// Where side `local_face` (2·axis + side) of the quadrilateral goes: (triangle, its edge).
/// Side ξ = −1 (vertices 0, 2) is B's edge (2, 0); ξ = +1 (1, 3) is A's edge (1, 2);
/// η = −1 (0, 1) is A's edge (0, 1); η = +1 (2, 3) is B's edge (1, 2).
constexpr std::array<std::pair<int, int>, 4> side_to_triangle{{{1, 2}, {0, 1}, {0, 0}, {1, 1}}};

} // namespace

Mesh<2> split_into_triangles(const Mesh<2>& quadrilaterals, bool bubbles) {
  FF_ASSERT(!quadrilaterals.is_simplex(), "split_into_triangles takes quadrilaterals");
  const int order = quadrilaterals.order;
  Mesh<2> triangles;
  triangles.order = order;
  triangles.shape = CellShape::Simplex;
  triangles.nodes = quadrilaterals.nodes;
  const int per_cell = order == 1 ? 3 : 6;
  triangles.cells.resize(per_cell, 2 * quadrilaterals.n_cells());
  for (Index cell = 0; cell < quadrilaterals.n_cells(); ++cell) {
    for (int t = 0; t < 2; ++t)
      for (int a = 0; a < per_cell; ++a) {
        const int local = order == 1 ? q1_triangles[t][a] : q2_triangles[t][a];
        triangles.cells(a, 2 * cell + t) = quadrilaterals.cells(local, cell);
      }
    if (order == 2) {
      const Index centre = quadrilaterals.cells(4, cell);
      triangles.nodes.col(centre) = 0.5 * (quadrilaterals.nodes.col(quadrilaterals.cells(0, cell)) +
                                           quadrilaterals.nodes.col(quadrilaterals.cells(8, cell)));
    }
  }
  for (const BoundaryFacet& facet : quadrilaterals.facets) {
    const auto [triangle, edge] = side_to_triangle[facet.local_face];
    triangles.facets.push_back({2 * facet.cell + triangle, edge, facet.label});
  }
  return bubbles ? with_bubble_nodes(triangles) : triangles;
}

template <int dim> Mesh<dim> with_bubble_nodes(const Mesh<dim>& simplices) {
  FF_ASSERT(simplices.is_simplex() && !simplices.bubbles, "bubbles go on plain simplices");
  Mesh<dim> enriched = simplices;
  enriched.bubbles = true;
  const int order = simplices.order, vertices = dim + 1;
  const int plain = simplices.nodes_per_cell();
  const int per_cell = nodes_per_cell<dim>(enriched.cell_type());
  const bool face_bubbles = dim == 3 && order == 2;
  // Face bubble nodes are shared by the two cells of a face: numbered by the face's
  // sorted vertices.
  std::map<std::array<Index, 3>, Index> face_node;
  std::vector<Point<dim>> added;
  const Index first_new = simplices.n_nodes();
  enriched.cells.resize(per_cell, simplices.n_cells());
  enriched.cells.topRows(plain) = simplices.cells;
  const auto position = [&](Index cell, const std::vector<int>& locals) {
    // The P2 (or P1) map at the centroid of the simplex spanned by the listed vertices:
    // P2's vertex function λ(2λ − 1) and edge function 4λλ' at λ = 1/n.
    const int n = static_cast<int>(locals.size());
    Point<dim> x = Point<dim>::Zero();
    if (order == 1) {
      for (int v : locals) x += simplices.nodes.col(simplices.cells(v, cell)) / n;
      return x;
    }
    const Real lambda = 1.0 / n;
    for (int i = 0; i < n; ++i) {
      x += lambda * (2 * lambda - 1) * simplices.nodes.col(simplices.cells(locals[i], cell));
      for (int j = i + 1; j < n; ++j) {
        const int mid = simplex_edge_midpoint<dim>(locals[i], locals[j]);
        x += 4 * lambda * lambda * simplices.nodes.col(simplices.cells(mid, cell));
      }
    }
    return x;
  };
  std::vector<int> all_vertices(vertices);
  for (int v = 0; v < vertices; ++v) all_vertices[v] = v;
  for (Index cell = 0; cell < simplices.n_cells(); ++cell) {
    int slot = plain;
    if (face_bubbles)
      for (int face = 0; face < vertices; ++face) {
        const std::vector<int> corners = simplex_face_vertices<dim>(face);
        std::array<Index, 3> key{};
        for (int k = 0; k < 3; ++k) key[k] = simplices.cells(corners[k], cell);
        std::sort(key.begin(), key.end());
        auto [entry, inserted] = face_node.try_emplace(key, first_new + Index(added.size()));
        if (inserted) added.push_back(position(cell, corners));
        enriched.cells(slot++, cell) = entry->second;
      }
    enriched.cells(slot, cell) = first_new + static_cast<Index>(added.size());
    added.push_back(position(cell, all_vertices));
  }
  enriched.nodes.conservativeResize(dim, first_new + static_cast<Index>(added.size()));
  for (std::size_t k = 0; k < added.size(); ++k)
    enriched.nodes.col(first_new + static_cast<Index>(k)) = added[k];
  return enriched;
}

template Mesh<2> with_bubble_nodes<2>(const Mesh<2>&);
template Mesh<3> with_bubble_nodes<3>(const Mesh<3>&);

} // namespace formflow::mesh
