// SPDX-License-Identifier: MIT
// Exit velocities and the flux balance (post/exit_flow.hpp).
#include "formflow/post/exit_flow.hpp"

#include "formflow/fem/dof_map.hpp"
#include "formflow/fem/reference_element.hpp"

#include <algorithm>
#include <limits>

namespace formflow::post {

template <int dim>
ExitFlow exit_flow(const assembly::FormingProblem<dim>& problem, const VectorX& u) {
  const mesh::Mesh<dim>& mesh = problem.discretisation().mesh();
  const bool axisymmetric = problem.discretisation().axisymmetric();
  fem::FacetValues<dim> face(mesh.cell_type(), fem::face_rule<dim>(mesh.cell_type()));
  typename fem::FacetValues<dim>::Gradients coordinates(dim, mesh.nodes_per_cell());
  ExitFlow flow;
  Real axial_integral = 0.0, entry_area = 0.0;
  std::vector<Index> exit_nodes;
  flow.velocity_min = std::numeric_limits<Real>::infinity();
  flow.velocity_max = -std::numeric_limits<Real>::infinity();
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    const bool exit = facet.label == mesh::BoundaryLabel::Front;
    const bool entry = facet.label == mesh::BoundaryLabel::Rear;
    const bool free = facet.label == mesh::BoundaryLabel::FreeEntry ||
                      facet.label == mesh::BoundaryLabel::FreeExit;
    if (!exit && !entry && !free && !mesh::is_contact(facet.label)) continue;
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, facet.cell));
    face.reinit(coordinates, facet.local_face);
    if (axisymmetric) face.weight_by_radius();
    for (int q = 0; q < face.n_points(); ++q) {
      Point<dim> velocity = Point<dim>::Zero();
      for (int a = 0; a < mesh.nodes_per_cell(); ++a)
        velocity += face.shape(q)[a] *
                    u.template segment<dim>(fem::dof_of<dim>(mesh.cells(a, facet.cell), 0));
      const Real normal_flux = velocity.dot(face.normal(q)) * face.JxW(q);
      if (exit) {
        flow.exit_flux += normal_flux;
        axial_integral += velocity[0] * face.JxW(q);
        flow.area += face.JxW(q);
      } else if (entry) {
        flow.entry_flux -= normal_flux;
        entry_area += face.JxW(q);
      } else if (free) {
        flow.free_surface_flux += normal_flux;
      } else {
        flow.wall_flux += normal_flux;
      }
    }
    if (!exit) continue;
    for (const int local : mesh.face_nodes(facet.local_face)) {
      const Index node = mesh.cells(local, facet.cell);
      const Real axial = u[fem::dof_of<dim>(node, 0)];
      flow.velocity_min = std::min(flow.velocity_min, axial);
      flow.velocity_max = std::max(flow.velocity_max, axial);
      if constexpr (dim == 2) exit_nodes.push_back(node);
    }
  }
  // A forming flow enters through the rear: a field without inflow there (a manufactured
  // solution on the unit box) has no exit speed to compare, nor a balance to divide by.
  flow.present = flow.area > 0 && entry_area > 0 && flow.entry_flux > 0;
  if (!flow.present) return ExitFlow{};
  flow.velocity_mean = axial_integral / flow.area;
  if (flow.velocity_mean > 0)
    flow.nonuniformity = (flow.velocity_max - flow.velocity_min) / flow.velocity_mean;
  flow.flux_balance = flow.exit_flux / flow.entry_flux - 1.0;
  std::sort(exit_nodes.begin(), exit_nodes.end());
  exit_nodes.erase(std::unique(exit_nodes.begin(), exit_nodes.end()), exit_nodes.end());
  for (const Index node : exit_nodes)
    flow.profile.push_back({mesh.nodes(1, node), u[fem::dof_of<dim>(node, 0)]});
  std::sort(flow.profile.begin(), flow.profile.end());
  return flow;
}

std::vector<ExitEdge> profile_exit_edges(const assembly::FormingProblem<3>& problem,
                                         const VectorX& u, const mesh::ProfileDie& die) {
  const mesh::Mesh<3>& mesh = problem.discretisation().mesh();
  fem::FacetValues<3> face(mesh.cell_type(), fem::face_rule<3>(mesh.cell_type()));
  typename fem::FacetValues<3>::Gradients coordinates(3, mesh.nodes_per_cell());
  const std::size_t n = die.outline.size();
  std::vector<ExitEdge> edges(n);
  std::vector<Real> axial(n, 0.0);
  for (std::size_t e = 0; e < n; ++e) {
    edges[e].from = die.outline[e];
    edges[e].to = die.outline[(e + 1) % n];
    edges[e].bearing_length = die.bearing(e);
  }
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != mesh::BoundaryLabel::Front) continue;
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, facet.cell));
    face.reinit(coordinates, facet.local_face);
    for (int q = 0; q < face.n_points(); ++q) {
      Point<3> at = Point<3>::Zero();
      Real velocity = 0.0;
      for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
        at += face.shape(q)[a] * coordinates.col(a);
        velocity += face.shape(q)[a] * u[fem::dof_of<3>(mesh.cells(a, facet.cell), 0)];
      }
      for (const auto& image : mesh::symmetry_images(die, {at.y(), at.z()})) {
        const std::size_t e = mesh::nearest_edge(die, image);
        edges[e].area += face.JxW(q);
        axial[e] += velocity * face.JxW(q);
      }
    }
  }
  for (std::size_t e = 0; e < n; ++e)
    edges[e].velocity_mean =
        edges[e].area > 0 ? axial[e] / edges[e].area : std::numeric_limits<Real>::quiet_NaN();
  return edges;
}

template ExitFlow exit_flow<2>(const assembly::FormingProblem<2>&, const VectorX&);
template ExitFlow exit_flow<3>(const assembly::FormingProblem<3>&, const VectorX&);

} // namespace formflow::post
