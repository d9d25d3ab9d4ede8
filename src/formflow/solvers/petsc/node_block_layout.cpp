// SPDX-License-Identifier: MIT
// The velocity block laid out node by node (constant block size) for AMG.
#include "formflow/solvers/petsc/node_block_layout.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>

namespace formflow::solvers::petsc {

NodeBlockLayout::NodeBlockLayout(int components, std::span<const Index> dof_of_velocity,
                                 Index n_rows)
    : components_(components) {
  FF_ASSERT(components >= 1, "a node has at least one component");
  const auto n_velocity = static_cast<Index>(dof_of_velocity.size());
  FF_ASSERT(n_velocity <= n_rows, "the velocity rows come first");
  // The nodes with a free dof, in the mesh's order, each given the next node slot.
  std::vector<Index> nodes(dof_of_velocity.begin(), dof_of_velocity.end());
  for (Index& node : nodes) node /= components;
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  n_velocity_embedded_ = static_cast<Index>(nodes.size()) * components;
  n_embedded_ = n_velocity_embedded_ + (n_rows - n_velocity);
  position_.resize(static_cast<std::size_t>(n_rows));
  std::vector<bool> used(static_cast<std::size_t>(n_velocity_embedded_), false);
  for (Index i = 0; i < n_velocity; ++i) {
    const Index dof = dof_of_velocity[i];
    const auto slot =
        std::lower_bound(nodes.begin(), nodes.end(), dof / components) - nodes.begin();
    const Index row = static_cast<Index>(slot) * components + dof % components;
    FF_ASSERT(!used[row], "each mesh dof is one free row");
    used[row] = true;
    position_[i] = row;
  }
  for (Index i = n_velocity; i < n_rows; ++i)
    position_[i] = n_velocity_embedded_ + (i - n_velocity);
  for (Index row = 0; row < n_velocity_embedded_; ++row)
    if (!used[row]) holes_.push_back(row);
}

VectorX NodeBlockLayout::embed(const VectorX& x) const {
  FF_ASSERT(x.size() == n_rows(), "a vector of the system");
  VectorX y = VectorX::Zero(n_embedded_);
  for (Index i = 0; i < n_rows(); ++i) y[position_[i]] = x[i];
  return y;
}

VectorX NodeBlockLayout::restrict(std::span<const Real> y) const {
  FF_ASSERT(static_cast<Index>(y.size()) == n_embedded_, "a vector of the layout");
  VectorX x(n_rows());
  for (Index i = 0; i < n_rows(); ++i) x[i] = y[static_cast<std::size_t>(position_[i])];
  return x;
}

} // namespace formflow::solvers::petsc
