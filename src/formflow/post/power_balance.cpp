// SPDX-License-Identifier: MIT
// Powers of the discrete terms and the mean hydrostatic pressure near the ram.
#include "formflow/physics/kinematics.hpp"
#include "formflow/post/post_process.hpp"

namespace formflow::post {

template <int dim>
PowerTerms compute_powers(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                          const std::vector<assembly::ContactPoint<dim>>& contact) {
  const auto& settings = problem.settings();
  const auto& mesh = problem.discretisation().mesh();
  fem::CellValues<dim> full_values(mesh.order, problem.discretisation().full_rule());
  fem::CellValues<dim> volumetric_values(mesh.order, problem.discretisation().volumetric_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  const bool deviatoric = settings.viscous_strain == physics::ViscousStrain::Deviatoric;
  const bool mixed = problem.multipliers() && problem.multipliers()->has_pressure_space();
  PowerTerms power;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    problem.discretisation().gather(cell, &u, coordinates, velocities);
    problem.discretisation().reinit(full_values, coordinates);
    problem.discretisation().reinit(volumetric_values, coordinates);
    for (int q = 0; q < full_values.n_points(); ++q) {
      const Tensor3 rate = problem.discretisation().strain_rate_at(full_values, velocities, q);
      const Real equivalent = physics::equivalent_strain_rate(rate);
      const Tensor3 measured = deviatoric ? physics::deviator(rate) : rate;
      power.plastic_dissipation += settings.law.dissipation(equivalent) * full_values.JxW(q);
      power.viscous_form += 2.0 / 3.0 * settings.law.secant_viscosity(equivalent) *
                            measured.cwiseProduct(measured).sum() * full_values.JxW(q);
    }
    if (mixed) continue; // the pressure term's power follows the loop
    for (int q = 0; q < volumetric_values.n_points(); ++q) {
      const Real volumetric =
          physics::velocity_gradient<dim>(velocities, volumetric_values.gradients(q)).trace() +
          problem.discretisation().hoop_rate_at(volumetric_values, velocities, q);
      power.volumetric_penalty +=
          volumetric * volumetric / settings.penalty.d * volumetric_values.JxW(q);
    }
  }
  // Mixed: ∫ σ_H div u dx = (1/d)‖P div u‖² for d > 0, → 0 for the exact constraint.
  if (mixed) power.volumetric_penalty = problem.multipliers()->pressure_power(u);
  for (const auto& point : contact) {
    // −σ_N u_N dΓ: u_N²/d_N for the penalty, → 0 for the exact contact.
    power.contact_penalty += point.contact_pressure * point.normal_velocity * point.weight;
    power.friction += point.friction_traction.dot(point.tangential_velocity) * point.weight;
  }
  return power;
}

template <int dim>
Real mean_pressure_of_cells_at(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                               mesh::BoundaryLabel label) {
  const auto& mesh = problem.discretisation().mesh();
  fem::CellValues<dim> values(mesh.order, problem.discretisation().volumetric_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  std::vector<bool> counted(mesh.n_cells(), false);
  Real integral = 0.0, area = 0.0;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != label || counted[facet.cell]) continue;
    counted[facet.cell] = true;
    problem.discretisation().gather(facet.cell, &u, coordinates, velocities);
    problem.discretisation().reinit(values, coordinates);
    if (problem.multipliers() && problem.multipliers()->has_pressure_space()) {
      integral -= problem.multipliers()->pressure_integral(facet.cell, u); // −σ_H dx
      for (int q = 0; q < values.n_points(); ++q) area += values.JxW(q);
      continue;
    }
    for (int q = 0; q < values.n_points(); ++q) {
      const Real volumetric =
          physics::velocity_gradient<dim>(velocities, values.gradients(q)).trace() +
          problem.discretisation().hoop_rate_at(values, velocities, q);
      integral += -volumetric / problem.settings().penalty.d * values.JxW(q); // −σ_H dx
      area += values.JxW(q);
    }
  }
  return area > 0 ? integral / area : 0.0;
}

template PowerTerms compute_powers<2>(const assembly::FormingProblem<2>&, const VectorX&,
                                      const std::vector<assembly::ContactPoint<2>>&);
template PowerTerms compute_powers<3>(const assembly::FormingProblem<3>&, const VectorX&,
                                      const std::vector<assembly::ContactPoint<3>>&);
template Real mean_pressure_of_cells_at<2>(const assembly::FormingProblem<2>&, const VectorX&,
                                           mesh::BoundaryLabel);
template Real mean_pressure_of_cells_at<3>(const assembly::FormingProblem<3>&, const VectorX&,
                                           mesh::BoundaryLabel);

} // namespace formflow::post
