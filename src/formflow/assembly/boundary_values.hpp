// SPDX-License-Identifier: MIT
// Dirichlet data on the whole boundary from a velocity field (manufactured solutions).
#pragma once

#include "formflow/assembly/constraints.hpp"

#include <functional>

namespace formflow::assembly {

/// Every component of every node on a labelled boundary facet prescribed to
/// `velocity(x_node)`. No driven dofs: the process force of such a problem is 0.
template <int dim>
DirichletConstraints
make_boundary_constraints(const mesh::Mesh<dim>& mesh,
                          const std::function<Point<dim>(const Point<dim>&)>& velocity);

} // namespace formflow::assembly
