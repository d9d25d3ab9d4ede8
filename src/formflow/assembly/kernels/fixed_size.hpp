// SPDX-License-Identifier: MIT
// Compile-time local sizes for the common elements: a kernel written for a node
// count N runs with fixed-size Eigen vectors and matrices (unrolled, vectorised,
// on the stack) for Q1/Q2 in 2D and Q1 in 3D, and with dynamic ones otherwise.
#pragma once

#include "formflow/core/types.hpp"

#include <type_traits>

namespace formflow::assembly {

/// Node count as a type: Eigen::Dynamic for the sizes not specialised.
template <int n_nodes> using NodeCount = std::integral_constant<int, n_nodes>;

/// Local dofs of a cell with `n_nodes` nodes (Eigen::Dynamic stays dynamic).
template <int dim, int n_nodes>
inline constexpr int local_size = n_nodes == Eigen::Dynamic ? Eigen::Dynamic : n_nodes* dim;

template <int dim, int n_nodes>
using LocalVector = Eigen::Matrix<Real, local_size<dim, n_nodes>, 1>;
template <int dim, int n_nodes>
using LocalMatrix = Eigen::Matrix<Real, local_size<dim, n_nodes>, local_size<dim, n_nodes>>;

/// Calls `kernel(NodeCount<N>{})` with N = n_nodes when it is a specialised size
/// (4, 9 in 2D; 8 in 3D; the 81×81 Q2 hexahedron stays dynamic: 52 kB per local
/// matrix is too much for the stack), else with Eigen::Dynamic.
template <int dim, class Kernel> void with_node_count(int n_nodes, Kernel&& kernel) {
  if constexpr (dim == 2) {
    if (n_nodes == 9) return kernel(NodeCount<9>{});
    if (n_nodes == 4) return kernel(NodeCount<4>{});
  } else if constexpr (dim == 3) {
    if (n_nodes == 8) return kernel(NodeCount<8>{});
  }
  kernel(NodeCount<Eigen::Dynamic>{});
}

} // namespace formflow::assembly
