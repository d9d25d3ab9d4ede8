// SPDX-License-Identifier: MIT
// make_cell_schedule: recursive coordinate bisection, then the seams again.
#include "formflow/assembly/cell_schedule.hpp"

#include <algorithm>
#include <numeric>

namespace formflow::assembly {

std::size_t CellSchedule::n_cells() const {
  std::size_t count = 0;
  for (const auto& phase : phases)
    for (const auto& block : phase) count += block.size();
  return count;
}

namespace {

/// Fewer cells than this are not cut again: the last phase's block.
constexpr std::size_t min_cells_to_cut = 64;
/// Phases cut before the last one (each one's seams are a thin layer of the one before).
constexpr int max_cut_phases = 4;

/// part[k] for cells[k]: `n_parts` parts by recursive coordinate bisection. The order
/// (coordinate, then position in `cells`) is total, so the parts do not depend on how
/// the sort breaks ties.
template <int dim> std::vector<int> bisect(const std::vector<Point<dim>>& centroids, int n_parts) {
  std::vector<int> part(centroids.size(), 0);
  std::vector<std::size_t> order(centroids.size());
  std::iota(order.begin(), order.end(), 0);
  struct Range {
    std::size_t begin, end;
    int first_part, parts;
  };
  std::vector<Range> pending{{0, order.size(), 0, n_parts}};
  while (!pending.empty()) {
    const Range range = pending.back();
    pending.pop_back();
    if (range.parts <= 1 || range.end - range.begin < 2) {
      for (std::size_t k = range.begin; k < range.end; ++k) part[order[k]] = range.first_part;
      continue;
    }
    Point<dim> low = centroids[order[range.begin]], high = low;
    for (std::size_t k = range.begin; k < range.end; ++k) {
      low = low.cwiseMin(centroids[order[k]]);
      high = high.cwiseMax(centroids[order[k]]);
    }
    int axis = 0;
    (high - low).maxCoeff(&axis);
    const int left_parts = range.parts / 2;
    const std::size_t middle = range.begin + (range.end - range.begin) *
                                                 static_cast<std::size_t>(left_parts) /
                                                 static_cast<std::size_t>(range.parts);
    std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(range.begin),
                     order.begin() + static_cast<std::ptrdiff_t>(middle),
                     order.begin() + static_cast<std::ptrdiff_t>(range.end),
                     [&](std::size_t a, std::size_t b) {
                       const Real xa = centroids[a][axis], xb = centroids[b][axis];
                       return xa < xb || (xa == xb && a < b);
                     });
    pending.push_back({range.begin, middle, range.first_part, left_parts});
    pending.push_back({middle, range.end, range.first_part + left_parts, range.parts - left_parts});
  }
  return part;
}

} // namespace

template <int dim>
CellSchedule make_cell_schedule(const mesh::Mesh<dim>& mesh, std::span<const Index> cells,
                                int n_blocks) {
  CellSchedule schedule;
  std::vector<Index> remaining(cells.begin(), cells.end());
  constexpr int unused = -1, shared = -2;
  std::vector<int> node_part(static_cast<std::size_t>(mesh.n_nodes()), unused);
  for (int phase = 0;; ++phase) {
    if (n_blocks <= 1 || remaining.size() < min_cells_to_cut || phase == max_cut_phases) {
      if (!remaining.empty()) schedule.phases.push_back({remaining});
      return schedule;
    }
    std::vector<Point<dim>> centroids(remaining.size(), Point<dim>::Zero());
    for (std::size_t k = 0; k < remaining.size(); ++k) {
      for (int a = 0; a < mesh.nodes_per_cell(); ++a)
        centroids[k] += mesh.nodes.col(mesh.cells(a, remaining[k]));
      centroids[k] /= mesh.nodes_per_cell();
    }
    const std::vector<int> part = bisect(centroids, n_blocks);
    for (std::size_t k = 0; k < remaining.size(); ++k)
      for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
        int& owner = node_part[static_cast<std::size_t>(mesh.cells(a, remaining[k]))];
        if (owner == unused)
          owner = part[k];
        else if (owner != part[k])
          owner = shared;
      }
    std::vector<std::vector<Index>> blocks(static_cast<std::size_t>(n_blocks));
    std::vector<Index> seams;
    for (std::size_t k = 0; k < remaining.size(); ++k) {
      bool seam = false;
      for (int a = 0; a < mesh.nodes_per_cell() && !seam; ++a)
        seam = node_part[static_cast<std::size_t>(mesh.cells(a, remaining[k]))] == shared;
      (seam ? seams : blocks[static_cast<std::size_t>(part[k])]).push_back(remaining[k]);
    }
    for (std::size_t k = 0; k < remaining.size(); ++k) // reset for the next phase
      for (int a = 0; a < mesh.nodes_per_cell(); ++a)
        node_part[static_cast<std::size_t>(mesh.cells(a, remaining[k]))] = unused;
    if (seams.size() == remaining.size()) { // no cut separated anything: one block
      schedule.phases.push_back({remaining});
      return schedule;
    }
    std::erase_if(blocks, [](const std::vector<Index>& block) { return block.empty(); });
    schedule.phases.push_back(std::move(blocks));
    remaining = std::move(seams);
  }
}

template CellSchedule make_cell_schedule<2>(const mesh::Mesh<2>&, std::span<const Index>, int);
template CellSchedule make_cell_schedule<3>(const mesh::Mesh<3>&, std::span<const Index>, int);

} // namespace formflow::assembly
