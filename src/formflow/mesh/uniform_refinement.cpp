// SPDX-License-Identifier: MIT
// Splitting tensor-product cells at their reference midpoints.
#include "formflow/mesh/uniform_refinement.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace formflow::mesh {

namespace {

/// Index of the lattice point `index` (x fastest) in a lattice of `n` per direction.
template <int dim> int flat(const std::array<int, dim>& index, int n) {
  int f = 0;
  for (int d = dim - 1; d >= 0; --d) f = f * n + index[d];
  return f;
}

/// The 1D Lagrange basis of `order` (nodes −1, +1 or −1, 0, +1) at ξ. The mesh layer
/// sits below fem, so the product basis of the geometry map is written out here.
Real lagrange_1d(int order, int node, Real xi) {
  if (order == 1) return node == 0 ? 0.5 * (1 - xi) : 0.5 * (1 + xi);
  if (node == 0) return 0.5 * xi * (xi - 1);
  if (node == 1) return (1 - xi) * (1 + xi);
  return 0.5 * xi * (xi + 1);
}

template <int dim> std::array<int, dim> unflat(int f, int n) {
  std::array<int, dim> index;
  for (int d = 0; d < dim; ++d) index[d] = f % n, f /= n;
  return index;
}

} // namespace

template <int dim> RefinedMesh<dim> refine_uniformly(const Mesh<dim>& coarse) {
  const int p = coarse.order;
  FF_ASSERT(p == 1 || p == 2, "cells of order 1 or 2");
  const int n_coarse = p + 1;   // coarse lattice points per direction
  const int n_fine = 2 * p + 1; // the fine lattice of one coarse cell
  int lattice = 1, children = 1, per_cell = 1;
  for (int d = 0; d < dim; ++d) lattice *= n_fine, children *= 2, per_cell *= n_coarse;

  RefinedMesh<dim> refined;
  Mesh<dim>& fine = refined.mesh;
  fine.order = p;
  fine.cells.resize(per_cell, coarse.n_cells() * children);
  refined.parent.resize(static_cast<std::size_t>(coarse.n_cells() * children));

  // A fine lattice point (index i per direction, 0 … 2p) lies between the coarse
  // lattice points ⌊i/2⌋ and ⌈i/2⌉ in each direction: the sorted global coarse nodes
  // at those corners name it, the same from every cell that shares it.
  std::map<std::vector<Index>, Index> node_of;
  std::vector<Point<dim>> positions;
  positions.reserve(static_cast<std::size_t>(coarse.n_nodes() * children));
  for (Index node = 0; node < coarse.n_nodes(); ++node)
    positions.emplace_back(coarse.nodes.col(node));
  std::vector<Index> lattice_node(static_cast<std::size_t>(lattice));
  for (Index cell = 0; cell < coarse.n_cells(); ++cell) {
    Eigen::Matrix<Real, dim, Eigen::Dynamic> geometry(dim, coarse.nodes_per_cell());
    for (int a = 0; a < coarse.nodes_per_cell(); ++a)
      geometry.col(a) = coarse.nodes.col(coarse.cells(a, cell));
    for (int f = 0; f < lattice; ++f) {
      const std::array<int, dim> index = unflat<dim>(f, n_fine);
      bool on_coarse = true;
      for (int d = 0; d < dim; ++d) on_coarse = on_coarse && index[d] % 2 == 0;
      if (on_coarse) {
        std::array<int, dim> half;
        for (int d = 0; d < dim; ++d) half[d] = index[d] / 2;
        lattice_node[f] = coarse.cells(flat<dim>(half, n_coarse), cell);
        continue;
      }
      std::vector<Index> key;
      const int corners = 1 << dim;
      for (int corner = 0; corner < corners; ++corner) {
        std::array<int, dim> at;
        for (int d = 0; d < dim; ++d)
          at[d] = ((corner >> d) & 1) ? (index[d] + 1) / 2 : index[d] / 2;
        key.push_back(coarse.cells(flat<dim>(at, n_coarse), cell));
      }
      std::sort(key.begin(), key.end());
      key.erase(std::unique(key.begin(), key.end()), key.end());
      const auto [found, inserted] = node_of.try_emplace(key, static_cast<Index>(positions.size()));
      if (inserted) {
        Point<dim> xi;
        for (int d = 0; d < dim; ++d) xi[d] = -1.0 + static_cast<Real>(index[d]) / p;
        VectorX values(per_cell);
        for (int a = 0; a < per_cell; ++a) {
          const std::array<int, dim> node = unflat<dim>(a, n_coarse);
          values[a] = 1.0;
          for (int d = 0; d < dim; ++d) values[a] *= lagrange_1d(p, node[d], xi[d]);
        }
        positions.emplace_back(geometry * values);
      }
      lattice_node[f] = found->second;
    }
    // Child c (bit d: the upper half in direction d) takes the lattice points
    // p·c_d … p·c_d + p of each direction.
    for (int child = 0; child < children; ++child) {
      const Index fine_cell = cell * children + child;
      refined.parent[static_cast<std::size_t>(fine_cell)] = cell;
      for (int a = 0; a < per_cell; ++a) {
        std::array<int, dim> index = unflat<dim>(a, n_coarse);
        for (int d = 0; d < dim; ++d) index[d] += p * ((child >> d) & 1);
        fine.cells(a, fine_cell) = lattice_node[flat<dim>(index, n_fine)];
      }
    }
  }
  fine.nodes.resize(dim, static_cast<Index>(positions.size()));
  for (std::size_t node = 0; node < positions.size(); ++node)
    fine.nodes.col(static_cast<Index>(node)) = positions[node];
  // Face 2·axis + side of a parent is face 2·axis + side of the children on that side.
  for (const BoundaryFacet& facet : coarse.facets) {
    const int axis = facet.local_face / 2, side = facet.local_face % 2;
    for (int child = 0; child < children; ++child)
      if (((child >> axis) & 1) == side)
        fine.facets.push_back({facet.cell * children + child, facet.local_face, facet.label});
  }
  return refined;
}

template RefinedMesh<2> refine_uniformly<2>(const Mesh<2>&);
template RefinedMesh<3> refine_uniformly<3>(const Mesh<3>&);

} // namespace formflow::mesh
