// SPDX-License-Identifier: MIT
// Rigid-body modes on the free velocity dofs.
#include "formflow/assembly/rigid_body_modes.hpp"

#include "formflow/fem/dof_map.hpp"

namespace formflow::assembly {

template <int dim>
std::vector<VectorX> rigid_body_modes(const mesh::Mesh<dim>& mesh, const ScatterPlan& plan) {
  constexpr int n_rotations = dim * (dim - 1) / 2;
  std::vector<VectorX> modes(dim + n_rotations, VectorX::Zero(plan.n_free()));
  // About the centroid: the rotations then stay well separated from the translations.
  const Eigen::Matrix<Real, dim, 1> centre = mesh.nodes.rowwise().mean();
  for (Index node = 0; node < mesh.n_nodes(); ++node) {
    const Eigen::Matrix<Real, dim, 1> x = mesh.nodes.col(node) - centre;
    for (int component = 0; component < dim; ++component) {
      const Index row = plan.free_index(fem::dof_of<dim>(node, component));
      if (row < 0) continue;
      modes[component][row] = 1.0;
      // Rotation in the (a, b) plane: u_a = −x_b, u_b = x_a.
      int rotation = dim;
      for (int a = 0; a < dim; ++a)
        for (int b = a + 1; b < dim; ++b, ++rotation) {
          if (component == a) modes[rotation][row] = -x[b];
          if (component == b) modes[rotation][row] = x[a];
        }
    }
  }
  return modes;
}

template std::vector<VectorX> rigid_body_modes<2>(const mesh::Mesh<2>&, const ScatterPlan&);
template std::vector<VectorX> rigid_body_modes<3>(const mesh::Mesh<3>&, const ScatterPlan&);

} // namespace formflow::assembly
