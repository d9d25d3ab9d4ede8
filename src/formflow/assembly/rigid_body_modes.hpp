// SPDX-License-Identifier: MIT
// The rigid-body motions restricted to the free velocity dofs: the near-null space
// that algebraic multigrid needs for an elasticity-like velocity block.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/mesh/mesh.hpp"

#include <vector>

namespace formflow::assembly {

/// The dim translations and the dim(dim−1)/2 rotations about the nodes' centroid,
/// each a vector over the free dofs of `plan` (ScatterPlan::free_index order; dof =
/// node·dim + component). The viscous operator annihilates them up to the boundary
/// rows, which is what smoothed aggregation asks for (PETSc GAMG's near-null space).
template <int dim>
std::vector<VectorX> rigid_body_modes(const mesh::Mesh<dim>& mesh, const ScatterPlan& plan);

} // namespace formflow::assembly
