// SPDX-License-Identifier: MIT
// The Γ3 nodes' normal velocity as a nodal field, and setting it.
#include "formflow/assembly/contact_normal_velocity.hpp"

#include "formflow/assembly/contact_frames.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"

namespace formflow::assembly {

template <int dim>
VectorX contact_normal_velocity(const Discretisation<dim>& discretisation,
                                const VectorX& velocity) {
  VectorX normal_velocity = VectorX::Zero(discretisation.mesh().n_nodes());
  for (const auto& [node, sum] : contact_node_normals(discretisation)) {
    const Real length = sum.norm();
    if (length == 0) continue;
    Real value = 0;
    for (int component = 0; component < dim; ++component)
      value += velocity[fem::dof_of<dim>(node, component)] * sum[component] / length;
    normal_velocity[node] = value;
  }
  return normal_velocity;
}

template <int dim>
void set_contact_normal_velocity(const Discretisation<dim>& discretisation,
                                 const VectorX& normal_velocity, VectorX& velocity) {
  FF_ASSERT(normal_velocity.size() == discretisation.mesh().n_nodes(), "a nodal field");
  const ScatterPlan& plan = discretisation.plan();
  for (const auto& [node, sum] : contact_node_normals(discretisation)) {
    const Real length = sum.norm();
    if (length == 0) continue;
    const Point<dim> normal = sum / length;
    Real current = 0, free_weight = 0;
    for (int component = 0; component < dim; ++component) {
      const Index dof = fem::dof_of<dim>(node, component);
      current += velocity[dof] * normal[component];
      if (plan.free_index(dof) >= 0) free_weight += normal[component] * normal[component];
    }
    // The node's free components move by t n_free: u·n changes by t |n_free|².
    if (free_weight == 0) continue; // nothing free to move (a prescribed node)
    const Real t = (normal_velocity[node] - current) / free_weight;
    for (int component = 0; component < dim; ++component) {
      const Index dof = fem::dof_of<dim>(node, component);
      if (plan.free_index(dof) >= 0) velocity[dof] += t * normal[component];
    }
  }
}

template VectorX contact_normal_velocity<2>(const Discretisation<2>&, const VectorX&);
template VectorX contact_normal_velocity<3>(const Discretisation<3>&, const VectorX&);
template void set_contact_normal_velocity<2>(const Discretisation<2>&, const VectorX&, VectorX&);
template void set_contact_normal_velocity<3>(const Discretisation<3>&, const VectorX&, VectorX&);

} // namespace formflow::assembly
