// SPDX-License-Identifier: MIT
// All-Dirichlet boundary data.
#include "formflow/assembly/boundary_values.hpp"

#include "formflow/fem/dof_map.hpp"

namespace formflow::assembly {

template <int dim>
DirichletConstraints
make_boundary_constraints(const mesh::Mesh<dim>& mesh,
                          const std::function<Point<dim>(const Point<dim>&)>& velocity) {
  const Index n_dofs = mesh.n_nodes() * dim;
  DirichletConstraints constraints{std::vector<bool>(n_dofs, false), VectorX::Zero(n_dofs), {}, {}};
  for (int label = 0; label < mesh::n_boundary_labels; ++label)
    for (Index node : nodes_on(mesh, static_cast<mesh::BoundaryLabel>(label))) {
      const Point<dim> value = velocity(mesh.nodes.col(node));
      for (int i = 0; i < dim; ++i) {
        constraints.prescribed[fem::dof_of<dim>(node, i)] = true;
        constraints.values[fem::dof_of<dim>(node, i)] = value[i];
      }
    }
  return constraints;
}

template DirichletConstraints
make_boundary_constraints<2>(const mesh::Mesh<2>&, const std::function<Point<2>(const Point<2>&)>&);
template DirichletConstraints
make_boundary_constraints<3>(const mesh::Mesh<3>&, const std::function<Point<3>(const Point<3>&)>&);

} // namespace formflow::assembly
