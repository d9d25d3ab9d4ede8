// SPDX-License-Identifier: MIT
// Dirichlet data from boundary labels.
#include "formflow/assembly/constraints.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/facet_axis.hpp"

#include <algorithm>
#include <optional>

namespace formflow::assembly {

template <int dim>
std::vector<Index> nodes_on(const mesh::Mesh<dim>& mesh, mesh::BoundaryLabel label) {
  std::vector<Index> nodes;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != label) continue;
    for (int local : mesh.face_nodes(facet.local_face))
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
  // Symmetry (Γ6: u_N = 0) first, so that the driven end's corner nodes keep their
  // normal component 0 and get u_x = u⁰. Each symmetry facet lies in a coordinate
  // plane (the generators' y = 0, z = 0 and the slab's z faces; a file's are checked
  // when it is read), so u_N = 0 fixes the component along that plane's axis; a node
  // where two symmetry planes meet (the edge y = z = 0) gets both.
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != mesh::BoundaryLabel::Symmetry) continue;
    const std::optional<int> axis = mesh::facet_normal_axis(mesh, facet);
    FF_ASSERT(axis.has_value(), "a symmetry facet lies in a coordinate plane");
    for (int local : mesh.face_nodes(facet.local_face))
      prescribe(mesh.cells(local, facet.cell), *axis, 0.0);
  }

  // The driven end is a plane x = const: u_x = u⁰ there; a sticking ram also holds
  // every tangential component (u_y, and u_z in 3D) at 0.
  const bool extrusion = process.type == physics::ProcessType::Extrusion;
  const bool sticking = extrusion && process.ram == physics::RamCondition::Sticking;
  constraints.driven_label = extrusion ? mesh::BoundaryLabel::Rear : mesh::BoundaryLabel::Front;
  for (Index node : nodes_on(mesh, constraints.driven_label)) {
    prescribe(node, 0, process.speed);
    constraints.driven_dofs.push_back(fem::dof_of<dim>(node, 0));
    if (sticking)
      for (int component = 1; component < dim; ++component) prescribe(node, component, 0.0);
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
