// SPDX-License-Identifier: MIT
// Numbering of the vector-valued velocity dofs: node-major, component fastest.
#pragma once

#include "formflow/core/types.hpp"

#include <vector>

namespace formflow::fem {

/// Global dof of component `component` of node `node`: node·dim + component.
/// Local dofs of a cell follow the same rule with local node numbers, so a
/// kernel's row a·dim + i is the i-th component at local node a.
template <int dim> constexpr Index dof_of(Index node, int component) {
  return node * dim + component;
}

/// Global dofs of a list of nodes, node-major.
template <int dim, typename Nodes> std::vector<Index> dofs_of_nodes(const Nodes& nodes) {
  std::vector<Index> dofs;
  dofs.reserve(nodes.size() * dim);
  for (Index node : nodes)
    for (int i = 0; i < dim; ++i) dofs.push_back(dof_of<dim>(node, i));
  return dofs;
}

} // namespace formflow::fem
