// SPDX-License-Identifier: MIT
// Integration-point quantities averaged to nodes, and cell means.
#include "formflow/core/error.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/fem/reference_element.hpp"
#include "formflow/fem/simplex_lagrange.hpp"
#include "formflow/physics/kinematics.hpp"
#include "formflow/post/post_process.hpp"

namespace formflow::post {

namespace {

/// Divides each accumulated nodal sum by the number of contributions (0 stays 0).
void average(VectorX& sum, const VectorX& count) {
  for (Index k = 0; k < sum.size(); ++k)
    if (count[k] > 0) sum[k] /= count[k];
}

} // namespace

template <int dim>
Fields nodal_fields(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                    const std::vector<assembly::ContactPoint<dim>>& contact) {
  const auto& mesh = problem.discretisation().mesh();
  const int n = mesh.nodes_per_cell();
  fem::CellValues<dim> at_nodes(mesh.cell_type(), fem::node_points<dim>(mesh.cell_type()));
  fem::CellValues<dim> full_values(mesh.cell_type(), problem.discretisation().full_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;

  Fields fields;
  fields.velocity = u;
  fields.equivalent_strain_rate = VectorX::Zero(mesh.n_nodes());
  fields.hydrostatic_stress = VectorX::Zero(mesh.n_nodes());
  fields.cell_equivalent_strain_rate = VectorX::Zero(mesh.n_cells());
  fields.cell_hydrostatic_stress = VectorX::Zero(mesh.n_cells());
  VectorX count = VectorX::Zero(mesh.n_nodes());
  const std::vector<assembly::CellPressure> pressures = problem.cell_pressures(u);
  auto rate_at = [&](const fem::CellValues<dim>& values, int q) {
    return physics::equivalent_strain_rate(
        problem.discretisation().strain_rate_at(values, velocities, q));
  };
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    problem.discretisation().gather(cell, &u, coordinates, velocities);
    at_nodes.reinit(coordinates);
    problem.discretisation().reinit(full_values, coordinates);
    Real area = 0.0;
    for (int q = 0; q < full_values.n_points(); ++q) {
      fields.cell_equivalent_strain_rate[cell] += rate_at(full_values, q) * full_values.JxW(q);
      area += full_values.JxW(q);
    }
    fields.cell_equivalent_strain_rate[cell] /= area;
    // σ_H from the term that carries it (ε̇_V/d, or the pressure space): its cell mean
    // and its values at the nodes.
    const assembly::CellPressure& pressure = pressures[cell];
    fields.cell_hydrostatic_stress[cell] = pressure.integral / area;
    const VectorX& nodal_stress = pressure.at_nodes;
    for (int a = 0; a < n; ++a) {
      const Index node = mesh.cells(a, cell);
      fields.equivalent_strain_rate[node] += rate_at(at_nodes, a);
      fields.hydrostatic_stress[node] += nodal_stress[a];
      count[node] += 1;
    }
  }
  average(fields.equivalent_strain_rate, count);
  average(fields.hydrostatic_stress, count);

  // Contact tractions: facet points → facet nodes, averaged where faces meet.
  fields.contact_pressure = VectorX::Zero(mesh.n_nodes());
  fields.friction_stress = VectorX::Zero(mesh.n_nodes());
  count.setZero();
  const int n_q = problem.discretisation().facet_rule().size();
  // Nodal contact normals put the points on the face nodes already. A triangle's edge is
  // a 1D Lagrange element with its nodes along it (mesh/cell_type.hpp), as a cube's face
  // is a (dim − 1)-cube: the tensor Gauss extrapolation serves both. A tetrahedron's face is
  // a triangle of the cell's order (and face bubble with P2+): the simplex fit.
  const MatrixX facet_to_nodes = [&]() -> MatrixX {
    if (problem.discretisation().contact_points_at_nodes()) return MatrixX::Identity(n_q, n_q);
    if constexpr (dim == 3)
      if (mesh.is_simplex())
        return fem::simplex_points_to_nodes<2>(mesh.order, mesh.bubbles && mesh.order == 2,
                                               problem.discretisation().facet_rule());
    return fem::gauss_to_nodes<dim - 1>(mesh.order, mesh.order + 1);
  }();
  VectorX pressure_at(n_q), friction_at(n_q);
  for (std::size_t first = 0; first < contact.size(); first += n_q) {
    const mesh::BoundaryFacet& facet = mesh.facets[contact[first].facet];
    for (int q = 0; q < n_q; ++q) {
      const auto& point = contact[first + q];
      pressure_at[q] = point.contact_pressure;
      friction_at[q] = point.friction_traction.norm();
    }
    const VectorX nodal_pressure = facet_to_nodes * pressure_at;
    const VectorX nodal_friction = facet_to_nodes * friction_at;
    const auto face_nodes = mesh.face_nodes(facet.local_face);
    for (std::size_t k = 0; k < face_nodes.size(); ++k) {
      const Index node = mesh.cells(face_nodes[k], facet.cell);
      fields.contact_pressure[node] += nodal_pressure[static_cast<Index>(k)];
      fields.friction_stress[node] += nodal_friction[static_cast<Index>(k)];
      count[node] += 1;
    }
  }
  average(fields.contact_pressure, count);
  average(fields.friction_stress, count);
  return fields;
}

template Fields nodal_fields<2>(const assembly::FormingProblem<2>&, const VectorX&,
                                const std::vector<assembly::ContactPoint<2>>&);
template Fields nodal_fields<3>(const assembly::FormingProblem<3>&, const VectorX&,
                                const std::vector<assembly::ContactPoint<3>>&);

} // namespace formflow::post
