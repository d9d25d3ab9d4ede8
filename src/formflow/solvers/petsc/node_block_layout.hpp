// SPDX-License-Identifier: MIT
// The velocity block of a saddle point laid out node by node, for the nodal and
// systems options of algebraic multigrid (issue 20, docs/petsc.md "Velocity AMG").
#pragma once

#include "formflow/core/types.hpp"

#include <span>
#include <vector>

namespace formflow::solvers::petsc {

/// BoomerAMG's nodal coarsening and GAMG's aggregation treat `components` consecutive rows
/// as one node (the matrix's block size), which the free-dof numbering is not: a node
/// with a prescribed component (a symmetry plane, the ram) has fewer rows. The layout
/// gives every node with a free velocity dof `components` rows, node-major as the mesh
/// numbers them (node·components + component), and fills the slots of its prescribed
/// components with decoupled rows (a diagonal entry, zero right-hand side, zero
/// solution), so the embedded system has the same solution on the free dofs and the
/// velocity block a constant block size. The pressure rows follow the velocity ones.
class NodeBlockLayout {
public:
  NodeBlockLayout() = default;
  /// `dof_of_velocity[i]`: the mesh dof node·components + component of free velocity
  /// row i (rows [0, dof_of_velocity.size()) of the system); the system has `n_rows`
  /// rows in all, the pressure's after the velocity's.
  NodeBlockLayout(int components, std::span<const Index> dof_of_velocity, Index n_rows);

  bool empty() const { return position_.empty(); }
  int components() const { return components_; }
  Index n_rows() const { return static_cast<Index>(position_.size()); }
  Index n_embedded() const { return n_embedded_; }
  Index n_velocity_embedded() const { return n_velocity_embedded_; }
  /// The layout's row of system row `row`.
  Index position(Index row) const { return position_[static_cast<std::size_t>(row)]; }
  /// The layout's rows that no system row fills (each gets a decoupled diagonal entry).
  std::span<const Index> holes() const { return holes_; }

  /// A vector of the system (n_rows) in the layout's rows, zero in the unused slots.
  VectorX embed(const VectorX& x) const;
  /// The system's rows of a vector of the layout (n_embedded): the inverse of embed.
  VectorX restrict(std::span<const Real> y) const;

private:
  int components_ = 1;
  std::vector<Index> position_; ///< system row → row of the layout
  std::vector<Index> holes_;    ///< the layout's rows that no system row fills
  Index n_embedded_ = 0, n_velocity_embedded_ = 0;
};

} // namespace formflow::solvers::petsc
