// SPDX-License-Identifier: MIT
// Dörfler marking and the next mesh's target sizes.
#include "formflow/post/adaptivity.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace formflow::post {

namespace {

/// The cells in order of |η_K|: largest first, or smallest first (ties keep their order).
std::vector<Index> cells_by_magnitude(const VectorX& indicators, bool largest_first) {
  std::vector<Index> order(static_cast<std::size_t>(indicators.size()));
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    const Real size_a = std::abs(indicators[a]), size_b = std::abs(indicators[b]);
    return largest_first ? size_a > size_b : size_a < size_b;
  });
  return order;
}

} // namespace

std::vector<bool> dorfler_marking(const VectorX& indicators, Real fraction) {
  std::vector<bool> marked(static_cast<std::size_t>(indicators.size()), false);
  const std::vector<Index> order = cells_by_magnitude(indicators, true);
  const Real total = indicators.cwiseAbs().sum();
  Real sum = 0;
  for (Index cell : order) {
    if (sum >= fraction * total || indicators[cell] == 0) break;
    marked[static_cast<std::size_t>(cell)] = true;
    sum += std::abs(indicators[cell]);
  }
  return marked;
}

Real cell_side(const mesh::Mesh<2>& mesh, Index cell) {
  const int n = mesh.nodes_per_side();
  const int corners[4] = {0, n - 1, n * n - 1, n * (n - 1)}; // counter-clockwise
  Real twice_area = 0;
  for (int k = 0; k < 4; ++k) {
    const auto a = mesh.nodes.col(mesh.cells(corners[k], cell));
    const auto b = mesh.nodes.col(mesh.cells(corners[(k + 1) % 4], cell));
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return std::sqrt(std::abs(twice_area) / 2);
}

std::vector<bool> coarsening_marking(const VectorX& indicators, Real fraction) {
  std::vector<bool> coarsened(static_cast<std::size_t>(indicators.size()), false);
  const std::vector<Index> order = cells_by_magnitude(indicators, false);
  const Real total = indicators.cwiseAbs().sum();
  Real sum = 0;
  for (Index cell : order) {
    sum += std::abs(indicators[cell]);
    if (sum > fraction * total) break;
    coarsened[static_cast<std::size_t>(cell)] = true;
  }
  return coarsened;
}

VectorX target_node_sizes(const mesh::Mesh<2>& mesh, const std::vector<bool>& marked,
                          const std::vector<bool>& coarsened, Real largest_size) {
  FF_ASSERT(static_cast<Index>(marked.size()) == mesh.n_cells() &&
                static_cast<Index>(coarsened.size()) == mesh.n_cells(),
            "one flag per cell");
  VectorX sizes = VectorX::Constant(mesh.n_nodes(), std::numeric_limits<Real>::infinity());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    const auto k = static_cast<std::size_t>(cell);
    Real side = cell_side(mesh, cell);
    if (marked[k])
      side *= 0.5;
    else if (coarsened[k])
      side = std::max(side, std::min(2 * side, largest_size)); // never below its own side
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      sizes[mesh.cells(a, cell)] = std::min(sizes[mesh.cells(a, cell)], side);
  }
  // Grading: within a cell, sizes differ by at most 2 (each sweep only lowers sizes,
  // toward the smallest, so the sweeps end).
  for (bool changed = true; changed;) {
    changed = false;
    for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
      Real smallest = std::numeric_limits<Real>::infinity();
      for (int a = 0; a < mesh.nodes_per_cell(); ++a)
        smallest = std::min(smallest, sizes[mesh.cells(a, cell)]);
      for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
        Real& size = sizes[mesh.cells(a, cell)];
        if (size > 2 * smallest) {
          size = 2 * smallest;
          changed = true;
        }
      }
    }
  }
  return sizes;
}

} // namespace formflow::post
