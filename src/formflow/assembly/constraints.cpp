// SPDX-License-Identifier: MIT
// Dirichlet data from boundary labels.
#include "formflow/assembly/constraints.hpp"

#include "formflow/fem/dof_map.hpp"

#include <algorithm>

namespace formflow::assembly {

template <int dim>
std::vector<Index> nodes_on(const mesh::Mesh<dim>& mesh, mesh::BoundaryLabel label) {
  std::vector<Index> nodes;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != label) continue;
    for (int local : mesh::face_local_nodes<dim>(mesh.nodes_per_side(), facet.local_face))
      nodes.push_back(mesh.cells(local, facet.cell));
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

template <int dim>
DirichletConstraints make_process_constraints(const mesh::Mesh<dim>& mesh,
                                              const physics::Process& process) {
  const Index n_dofs = mesh.n_nodes() * dim;
  DirichletConstraints constraints{std::vector<bool>(n_dofs, false), VectorX::Zero(n_dofs), {}, {}};
  auto prescribe = [&](Index node, int component, Real value) {
    const Index dof = fem::dof_of<dim>(node, component);
    constraints.prescribed[dof] = true;
    constraints.values[dof] = value;
  };
  // Symmetry first, so that the driven end's corner node keeps u_y = 0 and u_x = u⁰.
  for (Index node : nodes_on(mesh, mesh::BoundaryLabel::Symmetry)) prescribe(node, 1, 0.0);

  const bool extrusion = process.type == physics::ProcessType::Extrusion;
  constraints.driven_label = extrusion ? mesh::BoundaryLabel::Rear : mesh::BoundaryLabel::Front;
  for (Index node : nodes_on(mesh, constraints.driven_label)) {
    prescribe(node, 0, process.speed);
    constraints.driven_dofs.push_back(fem::dof_of<dim>(node, 0));
    if (extrusion && process.ram == physics::RamCondition::Sticking) prescribe(node, 1, 0.0);
  }
  return constraints;
}

template std::vector<Index> nodes_on<2>(const mesh::Mesh<2>&, mesh::BoundaryLabel);
template std::vector<Index> nodes_on<3>(const mesh::Mesh<3>&, mesh::BoundaryLabel);
template DirichletConstraints make_process_constraints<2>(const mesh::Mesh<2>&,
                                                          const physics::Process&);
template DirichletConstraints make_process_constraints<3>(const mesh::Mesh<3>&,
                                                          const physics::Process&);

} // namespace formflow::assembly
