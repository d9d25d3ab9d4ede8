// SPDX-License-Identifier: MIT
// Point location by buckets of cell bounding boxes and inverse isoparametric maps.
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/core/error.hpp"
#include "formflow/core/parallel_tasks.hpp"
#include "formflow/fem/reference_element.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace formflow::fem {

// Not an anonymous namespace: interpolate_nodal_field<dim> (external linkage) captures
// these types in its lambdas (-Wsubobject-linkage).
namespace point_location {

/// The buffers of reference_coordinates, reused from call to call (it runs for every
/// candidate cell of every target node: allocations were a fifth of its time).
template <int dim> struct InverseMapWork {
  Eigen::Matrix<Real, dim, Eigen::Dynamic> corners;
  VectorX values;
  Eigen::Matrix<Real, dim, Eigen::Dynamic> gradients;
};

/// How far `xi` lies outside the reference cell (0 inside), and `xi` moved onto it:
/// clamped to [-1, 1]^dim, or for a simplex clamped to ξ ≥ 0 and scaled to Σ ξ ≤ 1.
template <int dim> Real clamp_to_reference(bool simplex, Point<dim>& xi) {
  if (!simplex) {
    const Real outside = std::max(0.0, xi.cwiseAbs().maxCoeff() - 1.0);
    xi = xi.cwiseMax(-1.0).cwiseMin(1.0);
    return outside;
  }
  const Real outside = std::max({0.0, -xi.minCoeff(), xi.sum() - 1.0});
  xi = xi.cwiseMax(0.0);
  if (xi.sum() > 1.0) xi /= xi.sum();
  return outside;
}

/// Reference coordinates ξ of `x` in `cell` by Newton on x(ξ) = x, clamped to the
/// reference cell after each step (so a point outside the cell ends on its
/// boundary); returns the clamped ξ and, in `outside`, how far past the reference
/// cell the unclamped ξ lay (0 for a point inside).
template <int dim>
Point<dim> reference_coordinates(const mesh::Mesh<dim>& mesh, Index cell, const Point<dim>& x,
                                 Real& outside, InverseMapWork<dim>& work) {
  const int n_nodes = mesh.nodes_per_cell();
  work.corners.resize(dim, n_nodes);
  for (int a = 0; a < n_nodes; ++a) work.corners.col(a) = mesh.nodes.col(mesh.cells(a, cell));
  const bool simplex = mesh.is_simplex();
  // Start at the reference cell's centre.
  Point<dim> xi = simplex ? Point<dim>::Constant(1.0 / (dim + 1)) : Point<dim>::Zero();
  outside = 0.0;
  for (int k = 0; k < 20; ++k) {
    tabulate_shape<dim>(mesh.cell_type(), xi, work.values, work.gradients);
    const Point<dim> residual = work.corners * work.values - x;
    const Tensor2<dim> jacobian = work.corners * work.gradients.transpose();
    const Point<dim> step = jacobian.partialPivLu().solve(residual);
    xi -= step;
    outside = clamp_to_reference<dim>(simplex, xi);
    if (step.template lpNorm<Eigen::Infinity>() < 1e-13) break;
  }
  return xi;
}

/// A cell's box: its nodes' bounding box widened so that it holds the whole cell. The
/// map x(ξ) = Σ N_a(ξ) x_a is a convex combination for Q1 (no widening); for Q2 the
/// Lebesgue constant of the three-point quadratic is 5/4 per direction, so
/// |x(ξ) − c| ≤ (5/4)^dim max_a |x_a − c| with c the box's centre: the cell reaches
/// past its nodes' box by at most ((5/4)^dim − 1)/2 of the box's extent (0.28 in 2D,
/// 0.48 in 3D; near-affine cells stay far inside that). Plus round-off, and the 1e-9 of
/// the reference cell by which a point may lie outside and still be taken as inside.
template <int dim> struct CellBox {
  Point<dim> low, high;
  bool contains(const Point<dim>& x) const {
    return (x.array() >= low.array()).all() && (x.array() <= high.array()).all();
  }
};

template <int dim> std::vector<CellBox<dim>> cell_boxes(const mesh::Mesh<dim>& mesh) {
  std::vector<CellBox<dim>> boxes(static_cast<std::size_t>(mesh.n_cells()));
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Point<dim> low = Point<dim>::Constant(std::numeric_limits<Real>::max());
    Point<dim> high = -low;
    for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
      low = low.cwiseMin(mesh.nodes.col(mesh.cells(a, cell)));
      high = high.cwiseMax(mesh.nodes.col(mesh.cells(a, cell)));
    }
    // A straight-sided simplex is the hull of its vertices whatever its bubbles; a curved
    // P2 one is given the Q2 reach.
    const Real reach = mesh.order == 1 ? 0.0 : (std::pow(1.25, dim) - 1.0) / 2.0;
    const Point<dim> margin =
        reach * (high - low) + Point<dim>::Constant(1e-12) + 1e-9 * (high - low);
    boxes[static_cast<std::size_t>(cell)] = CellBox<dim>{low - margin, high + margin};
  }
  return boxes;
}

} // namespace point_location

/// Target nodes per task of the location loop (a few milliseconds of work).
constexpr Index nodes_per_task = 4096;

template <int dim>
VectorX interpolate_nodal_field(const mesh::Mesh<dim>& source, const VectorX& source_values,
                                int components, const mesh::Mesh<dim>& target) {
  using namespace point_location;
  FF_ASSERT(source_values.size() == source.n_nodes() * components,
            "source field has one value per node and component");
  // Buckets: a uniform grid over the source's bounding box, each cell entered in
  // every bucket its (slightly enlarged) bounding box touches.
  const Point<dim> low = source.nodes.rowwise().minCoeff(),
                   high = source.nodes.rowwise().maxCoeff();
  const Real per_direction = std::ceil(std::pow(static_cast<Real>(source.n_cells()), 1.0 / dim));
  const int n_buckets = std::max(1, static_cast<int>(per_direction));
  const Point<dim> width = ((high - low) / n_buckets).cwiseMax(1e-300);
  auto bucket_of = [&](const Point<dim>& x, int direction) {
    return std::clamp(
        static_cast<int>(std::floor((x[direction] - low[direction]) / width[direction])), 0,
        n_buckets - 1);
  };
  auto flat = [&](const std::array<int, dim>& index) {
    int f = 0;
    for (int d = dim - 1; d >= 0; --d) f = f * n_buckets + index[d];
    return f;
  };
  int total = 1;
  for (int d = 0; d < dim; ++d) total *= n_buckets;
  std::vector<std::vector<Index>> buckets(total);
  const std::vector<CellBox<dim>> boxes = cell_boxes(source);
  for (Index cell = 0; cell < source.n_cells(); ++cell) {
    const CellBox<dim>& box = boxes[static_cast<std::size_t>(cell)];
    std::array<int, dim> first, last, index;
    for (int d = 0; d < dim; ++d)
      first[d] = bucket_of(box.low, d), last[d] = bucket_of(box.high, d);
    index = first;
    while (true) {
      buckets[flat(index)].push_back(cell);
      int d = 0;
      while (d < dim && ++index[d] > last[d]) index[d] = first[d], ++d;
      if (d == dim) break;
    }
  }

  VectorX result(target.n_nodes() * components);
  // Each target node is located on its own: ranges of nodes on the machine's threads.
  const Index n_tasks = (target.n_nodes() + nodes_per_task - 1) / nodes_per_task;
  run_tasks(static_cast<std::size_t>(n_tasks), compute_threads(), [&](std::size_t task) {
    InverseMapWork<dim> work;
    const Index first = static_cast<Index>(task) * nodes_per_task;
    const Index last = std::min(target.n_nodes(), first + nodes_per_task);
    for (Index node = first; node < last; ++node) {
      const Point<dim> x = target.nodes.col(node);
      std::array<int, dim> index;
      for (int d = 0; d < dim; ++d) index[d] = bucket_of(x, d);
      // The cell containing x, or the one it lies least outside of: first in its
      // bucket, then (a boundary node of a curved outline) in every cell.
      Index best_cell = -1;
      Point<dim> best_xi;
      Real best_outside = std::numeric_limits<Real>::max();
      // First the cells whose box holds x (no other cell can contain it); the rest only
      // when none does (a boundary node just outside a curved outline: the least outside).
      bool boxes_only = true;
      auto try_cells = [&](const std::vector<Index>& cells) {
        for (Index cell : cells) {
          if (boxes_only && !boxes[static_cast<std::size_t>(cell)].contains(x)) continue;
          Real outside = 0;
          const Point<dim> xi = reference_coordinates(source, cell, x, outside, work);
          if (outside < best_outside) best_outside = outside, best_cell = cell, best_xi = xi;
          if (outside <= 1e-9) return;
        }
      };
      try_cells(buckets[flat(index)]);
      if (best_outside > 1e-9) {
        boxes_only = false;
        try_cells(buckets[flat(index)]);
      }
      if (best_outside > 1e-9) {
        // The neighbouring buckets (a node just outside a curved source outline).
        std::array<int, dim> offset;
        offset.fill(-1);
        while (true) {
          std::array<int, dim> neighbour;
          bool inside = true;
          for (int d = 0; d < dim; ++d) {
            neighbour[d] = index[d] + offset[d];
            inside = inside && neighbour[d] >= 0 && neighbour[d] < n_buckets;
          }
          if (inside) try_cells(buckets[flat(neighbour)]);
          int d = 0;
          while (d < dim && ++offset[d] > 1) offset[d] = -1, ++d;
          if (d == dim) break;
        }
      }
      FF_ASSERT(best_cell >= 0, "every target node lies near some source cell");
      tabulate_shape<dim>(source.cell_type(), best_xi, work.values, work.gradients);
      for (int c = 0; c < components; ++c) {
        Real value = 0;
        for (int a = 0; a < source.nodes_per_cell(); ++a)
          value += work.values[a] * source_values[source.cells(a, best_cell) * components + c];
        result[node * components + c] = value;
      }
    }
  });
  return result;
}

template VectorX interpolate_nodal_field<2>(const mesh::Mesh<2>&, const VectorX&, int,
                                            const mesh::Mesh<2>&);
template VectorX interpolate_nodal_field<3>(const mesh::Mesh<3>&, const VectorX&, int,
                                            const mesh::Mesh<3>&);

} // namespace formflow::fem
