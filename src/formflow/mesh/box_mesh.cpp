// SPDX-License-Identifier: MIT
// Structured box mesh with smooth or random interior-node perturbation.
#include "formflow/mesh/box_mesh.hpp"

#include "formflow/core/error.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace formflow::mesh {

namespace {

/// Vertex lattice (n_x+1) × (n_y+1), x fastest, after the distortion.
std::vector<Point<2>> vertex_lattice(const Point<2>& lower, const Point<2>& upper, int n_x, int n_y,
                                     const BoxDistortion& distortion) {
  const Point<2> size = upper - lower;
  const Real cell_x = size.x() / n_x, cell_y = size.y() / n_y;
  std::mt19937_64 random(distortion.seed);
  std::uniform_real_distribution<Real> offset(-1.0, 1.0);
  std::vector<Point<2>> vertices;
  for (int j = 0; j <= n_y; ++j)
    for (int i = 0; i <= n_x; ++i) {
      const Real s = static_cast<Real>(i) / n_x, t = static_cast<Real>(j) / n_y;
      Point<2> x(lower.x() + s * size.x(), lower.y() + t * size.y());
      const bool interior = i > 0 && i < n_x && j > 0 && j < n_y;
      if (interior && distortion.kind == Distortion::Smooth) {
        // One fixed map for the whole ladder, vanishing on the boundary; its
        // two components differ so that the cells are not parallelograms.
        const Real bump = std::sin(std::numbers::pi * s) * std::sin(std::numbers::pi * t);
        x.x() += distortion.amplitude * size.x() * bump * std::sin(2 * std::numbers::pi * t);
        x.y() += distortion.amplitude * size.y() * bump * std::sin(2 * std::numbers::pi * s);
      } else if (interior && distortion.kind == Distortion::Random) {
        x.x() += distortion.amplitude * cell_x * offset(random);
        x.y() += distortion.amplitude * cell_y * offset(random);
      }
      vertices.push_back(x);
    }
  return vertices;
}

} // namespace

Mesh<2> make_box_mesh(const Point<2>& lower, const Point<2>& upper, int n_x, int n_y, int order,
                      const BoxDistortion& distortion) {
  FF_ASSERT(n_x > 0 && n_y > 0, "a box mesh needs at least one cell per direction");
  FF_ASSERT(order == 1 || order == 2, "order must be 1 or 2");
  FF_ASSERT((upper - lower).minCoeff() > 0, "the box must have positive size");
  const std::vector<Point<2>> vertices = vertex_lattice(lower, upper, n_x, n_y, distortion);
  auto vertex = [&](int i, int j) { return vertices[j * (n_x + 1) + i]; };

  // Node lattice with `order` nodes per cell side; node (I, J) lies in cell
  // (I/order, J/order) at local lattice position (I%order, J%order), placed by
  // that cell's bilinear map (so shared nodes get the same position from either cell).
  const int lattice_x = n_x * order, lattice_y = n_y * order;
  Mesh<2> mesh;
  mesh.order = order;
  mesh.nodes.resize(2, (lattice_x + 1) * (lattice_y + 1));
  for (int J = 0; J <= lattice_y; ++J)
    for (int I = 0; I <= lattice_x; ++I) {
      const int ci = std::min(I / order, n_x - 1), cj = std::min(J / order, n_y - 1);
      const Real s = static_cast<Real>(I - ci * order) / order;
      const Real t = static_cast<Real>(J - cj * order) / order;
      mesh.nodes.col(J * (lattice_x + 1) + I) =
          (1 - s) * (1 - t) * vertex(ci, cj) + s * (1 - t) * vertex(ci + 1, cj) +
          (1 - s) * t * vertex(ci, cj + 1) + s * t * vertex(ci + 1, cj + 1);
    }

  const int n_side = order + 1;
  mesh.cells.resize(n_side * n_side, n_x * n_y);
  for (int cj = 0; cj < n_y; ++cj)
    for (int ci = 0; ci < n_x; ++ci) {
      const Index cell = cj * n_x + ci;
      for (int b = 0; b < n_side; ++b)
        for (int a = 0; a < n_side; ++a)
          mesh.cells(b * n_side + a, cell) = (cj * order + b) * (lattice_x + 1) + ci * order + a;
      if (ci == 0) mesh.facets.push_back({cell, 0, BoundaryLabel::Rear});
      if (ci == n_x - 1) mesh.facets.push_back({cell, 1, BoundaryLabel::Front});
      if (cj == 0) mesh.facets.push_back({cell, 2, BoundaryLabel::Symmetry});
      if (cj == n_y - 1) mesh.facets.push_back({cell, 3, BoundaryLabel::FreeExit});
    }
  return mesh;
}

} // namespace formflow::mesh
