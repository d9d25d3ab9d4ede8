// SPDX-License-Identifier: MIT
// Tetrahedra from a hexahedral mesh, conforming by the least-vertex diagonal rule.
#include "formflow/mesh/tetrahedral_split.hpp"

#include "formflow/core/error.hpp"
#include "formflow/mesh/simplex_split.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <optional>

namespace formflow::mesh {

namespace {

// A hexahedron's vertex v (0 … 7) has the bits (i, j, k) of its lattice corner: bit `axis`
// of v is 0 on the face ξ_axis = −1 and 1 on ξ_axis = +1.
int bit_of(int v, int axis) {
  return (v >> axis) & 1;
}

/// The local node of a hexahedron at doubled lattice coordinates (a, b, c) ∈ {0, 1, 2}³:
/// a vertex has even ones (Q1 numbering i + 2j + 4k), the Q2 lattice all nine per layer.
int lattice_node(int order, int a, int b, int c) {
  if (order == 1) return a / 2 + 2 * (b / 2) + 4 * (c / 2);
  return a + 3 * b + 9 * c;
}

int vertex_node(int order, int v) {
  return lattice_node(order, 2 * bit_of(v, 0), 2 * bit_of(v, 1), 2 * bit_of(v, 2));
}

/// The Q2 node halfway between vertices u and w (an edge, a face diagonal or a main
/// diagonal of the lattice).
int midpoint_node(int u, int w) {
  return lattice_node(2, bit_of(u, 0) + bit_of(w, 0), bit_of(u, 1) + bit_of(w, 1),
                      bit_of(u, 2) + bit_of(w, 2));
}

/// The vertex of face `face` (2·axis + side) diagonally across from its vertex v.
int across_face(int v, int face) {
  return v ^ (7 ^ (1 << (face / 2)));
}

bool on_face(int v, int face) {
  return bit_of(v, face / 2) == face % 2;
}

/// The face's vertex of least global node: its diagonal runs from there to across_face.
int least_vertex(const std::array<Index, 8>& global, int face) {
  std::optional<int> least;
  for (int v = 0; v < 8; ++v)
    if (on_face(v, face) && (!least || global[v] < global[*least])) least = v;
  return *least;
}

/// The main diagonal (a, a ^ 7) whose Kuhn split cuts every face along `diagonal_from`'s
/// diagonals, if any.
std::optional<int> kuhn_diagonal(const std::array<int, 6>& diagonal_from) {
  for (int a = 0; a < 4; ++a) {
    bool fits = true;
    for (int face = 0; face < 6 && fits; ++face) {
      const int end = on_face(a, face) ? a : (a ^ 7); // the diagonal's end on this face
      fits = end == diagonal_from[face] || end == across_face(diagonal_from[face], face);
    }
    if (fits) return a;
  }
  return std::nullopt;
}

/// A tetrahedron being built: its four vertices as mesh nodes.
using Tetrahedron = std::array<Index, 4>;

} // namespace

Mesh<3> split_into_tetrahedra(const Mesh<3>& hexahedra, bool bubbles) {
  FF_ASSERT(!hexahedra.is_simplex(), "split_into_tetrahedra takes hexahedra");
  const int order = hexahedra.order;
  std::vector<Point<3>> nodes;
  nodes.reserve(static_cast<std::size_t>(hexahedra.n_nodes()));
  for (Index n = 0; n < hexahedra.n_nodes(); ++n) nodes.emplace_back(hexahedra.nodes.col(n));
  const auto add_node = [&nodes](const Point<3>& x) {
    nodes.push_back(x);
    return static_cast<Index>(nodes.size() - 1);
  };

  std::vector<std::array<Index, 10>> tetrahedra; // vertices, then the P2 edge midpoints
  std::vector<std::size_t> first_of_cell{0};
  for (Index cell = 0; cell < hexahedra.n_cells(); ++cell) {
    std::array<Index, 8> global{};
    for (int v = 0; v < 8; ++v) global[v] = hexahedra.cells(vertex_node(order, v), cell);
    std::array<int, 6> diagonal_from{};
    for (int face = 0; face < 6; ++face) diagonal_from[face] = least_vertex(global, face);

    // Each tetrahedron as hexahedron vertices (0 … 7) or the centre (8).
    constexpr int centre = 8;
    std::vector<std::array<int, 4>> pieces;
    const std::optional<int> main = kuhn_diagonal(diagonal_from);
    if (main) {
      std::array<int, 3> axes{0, 1, 2};
      do { // the path from a to a ^ 7 flipping one bit at a time, in this axis order
        std::array<int, 4> path{*main, 0, 0, 0};
        for (int s = 0; s < 3; ++s) path[s + 1] = path[s] ^ (1 << axes[s]);
        pieces.push_back(path);
      } while (std::next_permutation(axes.begin(), axes.end()));
    } else {
      for (int face = 0; face < 6; ++face) {
        const int m = diagonal_from[face], n = across_face(m, face);
        for (int v = 0; v < 8; ++v)
          if (on_face(v, face) && v != m && v != n) pieces.push_back({centre, m, n, v});
      }
    }

    Index centre_node = -1;
    std::array<Index, 8> centre_midpoint{};
    centre_midpoint.fill(-1);
    if (!main) {
      if (order == 2) {
        centre_node = hexahedra.cells(lattice_node(2, 1, 1, 1), cell);
      } else {
        Point<3> x = Point<3>::Zero();
        for (const Index g : global) x += nodes[static_cast<std::size_t>(g)] / 8.0;
        centre_node = add_node(x);
      }
    } else if (order == 2) { // the main diagonal's midpoint, on the straight diagonal
      const Index mid = hexahedra.cells(midpoint_node(*main, *main ^ 7), cell);
      nodes[static_cast<std::size_t>(mid)] =
          0.5 * (nodes[static_cast<std::size_t>(global[*main])] +
                 nodes[static_cast<std::size_t>(global[*main ^ 7])]);
    }
    const auto node_of = [&](int local) { return local == centre ? centre_node : global[local]; };
    const auto midpoint = [&](int u, int w) -> Index {
      if (u == centre || w == centre) {
        const int v = u == centre ? w : u;
        if (centre_midpoint[v] < 0)
          centre_midpoint[v] = add_node(0.5 * (nodes[static_cast<std::size_t>(centre_node)] +
                                               nodes[static_cast<std::size_t>(global[v])]));
        return centre_midpoint[v];
      }
      return hexahedra.cells(midpoint_node(u, w), cell);
    };

    for (std::array<int, 4> piece : pieces) {
      const auto x = [&](int k) { return nodes[static_cast<std::size_t>(node_of(piece[k]))]; };
      Eigen::Matrix3d edges;
      for (int k = 0; k < 3; ++k) edges.col(k) = x(k + 1) - x(0);
      if (edges.determinant() < 0) std::swap(piece[1], piece[2]);
      std::array<Index, 10> tet{};
      for (int k = 0; k < 4; ++k) tet[k] = node_of(piece[k]);
      if (order == 2) {
        constexpr std::array<std::array<int, 2>, 6> edge_ends{
            {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}}; // mesh/cell_type.hpp: 4 … 9
        for (int e = 0; e < 6; ++e)
          tet[4 + e] = midpoint(piece[edge_ends[e][0]], piece[edge_ends[e][1]]);
      }
      tetrahedra.push_back(tet);
    }
    first_of_cell.push_back(tetrahedra.size());
  }

  Mesh<3> split;
  split.order = order;
  split.shape = CellShape::Simplex;
  split.nodes.resize(3, static_cast<Index>(nodes.size()));
  for (std::size_t n = 0; n < nodes.size(); ++n) split.nodes.col(static_cast<Index>(n)) = nodes[n];
  const int per_cell = order == 1 ? 4 : 10;
  split.cells.resize(per_cell, static_cast<Index>(tetrahedra.size()));
  for (std::size_t t = 0; t < tetrahedra.size(); ++t)
    for (int a = 0; a < per_cell; ++a) split.cells(a, static_cast<Index>(t)) = tetrahedra[t][a];

  // A hexahedron face's two triangles are faces of that cell's tetrahedra (both splits
  // cut it along its least-vertex diagonal): each facet becomes the two that hold them.
  for (const BoundaryFacet& facet : hexahedra.facets) {
    std::array<Index, 8> global{};
    for (int v = 0; v < 8; ++v) global[v] = hexahedra.cells(vertex_node(order, v), facet.cell);
    std::vector<Index> corners;
    for (int v = 0; v < 8; ++v)
      if (on_face(v, facet.local_face)) corners.push_back(global[v]);
    int found = 0;
    for (std::size_t t = first_of_cell[static_cast<std::size_t>(facet.cell)];
         t < first_of_cell[static_cast<std::size_t>(facet.cell) + 1]; ++t)
      for (int k = 0; k < 4; ++k) { // face k: the three vertices other than k
        bool on = true;
        for (int a = 0; a < 4 && on; ++a)
          if (a != k)
            on = std::find(corners.begin(), corners.end(), tetrahedra[t][a]) != corners.end();
        if (!on) continue;
        split.facets.push_back({static_cast<Index>(t), k, facet.label});
        ++found;
      }
    FF_ASSERT(found == 2, "a hexahedron face is two faces of its tetrahedra");
  }
  return bubbles ? with_bubble_nodes(split) : split;
}

} // namespace formflow::mesh
