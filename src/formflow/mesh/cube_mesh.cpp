// SPDX-License-Identifier: MIT
// A distorted lattice of hexahedra on the unit cube.
#include "formflow/mesh/cube_mesh.hpp"

#include "formflow/core/error.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace formflow::mesh {

namespace {

/// Vertex lattice (n+1)³, x fastest, after the distortion.
std::vector<Point<3>> vertex_lattice(int n, const BoxDistortion& distortion) {
  constexpr Real pi = std::numbers::pi;
  std::mt19937_64 random(distortion.seed);
  std::uniform_real_distribution<Real> offset(-1.0, 1.0);
  std::vector<Point<3>> vertices;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Point<3> x(static_cast<Real>(i) / n, static_cast<Real>(j) / n, static_cast<Real>(k) / n);
        const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        if (interior && distortion.kind == Distortion::Smooth) {
          const Point<3> s = x;
          const Real bump = std::sin(pi * s[0]) * std::sin(pi * s[1]) * std::sin(pi * s[2]);
          for (int d = 0; d < 3; ++d)
            x[d] += distortion.amplitude * bump * std::sin(2 * pi * s[(d + 1) % 3]);
        } else if (interior && distortion.kind == Distortion::Random) {
          for (int d = 0; d < 3; ++d) x[d] += distortion.amplitude / n * offset(random);
        }
        vertices.push_back(x);
      }
  return vertices;
}

} // namespace

Mesh<3> make_unit_cube_mesh(int n, int order, const BoxDistortion& distortion) {
  FF_ASSERT(n > 0 && (order == 1 || order == 2), "cells and order");
  const std::vector<Point<3>> vertices = vertex_lattice(n, distortion);
  const auto vertex = [&](int i, int j, int k) {
    return vertices[(k * (n + 1) + j) * (n + 1) + i];
  };
  const int lattice = n * order + 1;
  const auto node_index = [&](int i, int j, int k) {
    return (static_cast<Index>(k) * lattice + j) * lattice + i;
  };

  Mesh<3> mesh;
  mesh.order = order;
  mesh.nodes.resize(3, static_cast<Index>(lattice) * lattice * lattice);
  for (int K = 0; K < lattice; ++K)
    for (int J = 0; J < lattice; ++J)
      for (int I = 0; I < lattice; ++I) {
        // Node (I, J, K) by the trilinear map of the cell that holds it (shared nodes
        // get the same position from either cell: the maps agree on shared faces).
        const std::array<int, 3> at = {I, J, K};
        std::array<int, 3> cell;
        std::array<Real, 3> t;
        for (int d = 0; d < 3; ++d) {
          cell[d] = std::min(at[d] / order, n - 1);
          t[d] = static_cast<Real>(at[d] - cell[d] * order) / order;
        }
        Point<3> x = Point<3>::Zero();
        for (int c = 0; c < 8; ++c) {
          const int a = c & 1, b = (c >> 1) & 1, e = (c >> 2) & 1;
          const Real weight = (a ? t[0] : 1 - t[0]) * (b ? t[1] : 1 - t[1]) * (e ? t[2] : 1 - t[2]);
          x += weight * vertex(cell[0] + a, cell[1] + b, cell[2] + e);
        }
        mesh.nodes.col(node_index(I, J, K)) = x;
      }

  const int n_side = order + 1;
  const std::array<BoundaryLabel, 6> labels = {BoundaryLabel::Rear,     BoundaryLabel::Front,
                                               BoundaryLabel::Symmetry, BoundaryLabel::FreeExit,
                                               BoundaryLabel::Symmetry, BoundaryLabel::FreeExit};
  mesh.cells.resize(n_side * n_side * n_side, static_cast<Index>(n) * n * n);
  for (int ck = 0; ck < n; ++ck)
    for (int cj = 0; cj < n; ++cj)
      for (int ci = 0; ci < n; ++ci) {
        const Index cell = (static_cast<Index>(ck) * n + cj) * n + ci;
        for (int c = 0; c < n_side; ++c)
          for (int b = 0; b < n_side; ++b)
            for (int a = 0; a < n_side; ++a)
              mesh.cells((c * n_side + b) * n_side + a, cell) =
                  node_index(ci * order + a, cj * order + b, ck * order + c);
        const std::array<int, 3> at = {ci, cj, ck};
        for (int axis = 0; axis < 3; ++axis) {
          if (at[axis] == 0) mesh.facets.push_back({cell, 2 * axis, labels[2 * axis]});
          if (at[axis] == n - 1) mesh.facets.push_back({cell, 2 * axis + 1, labels[2 * axis + 1]});
        }
      }
  return mesh;
}

} // namespace formflow::mesh
