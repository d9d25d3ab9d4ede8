// SPDX-License-Identifier: MIT
// Final evaluation of a converged (or last) iterate.
#include "formflow/post/post_process.hpp"

#include "formflow/mesh/cell_diameter.hpp"
#include "formflow/post/exit_flow.hpp"

namespace formflow::post {

template <int dim>
void evaluate_results(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                      Results& results, const assembly::FrictionMultipliers<dim>* multipliers,
                      Real stick_speed) {
  ScopedTimer timer(results.timing, "post");
  const Real speed = problem.settings().process.speed;
  const Real height = problem.discretisation().driven_height();

  assembly::LinearSystem system = problem.discretisation().plan().make_system();
  problem.assemble(&u, system, multipliers);
  auto contact = problem.contact_state(u, multipliers);
  // Exact friction by Newton: its stop rule resolves slips to δ u⁰, not the tractions of
  // the near-rigid dead-metal zone, whose active set keeps changing while u is settled
  // (docs/friction.md "Stop rule"): stick is what the velocity shows.
  if (stick_speed > 0)
    for (auto& point : contact)
      point.sticking =
          point.friction_threshold > 0 && point.tangential_velocity.norm() <= stick_speed;

  results.n_cells = problem.discretisation().mesh().n_cells();
  results.dimension = dim;
  results.n_nodes = problem.discretisation().mesh().n_nodes();
  results.n_dofs = problem.discretisation().n_dofs();
  const mesh::CellDiameterRange diameters =
      mesh::cell_diameter_range(problem.discretisation().mesh());
  results.min_cell_diameter = diameters.smallest;
  results.max_cell_diameter = diameters.largest;
  results.power = compute_powers(problem, u, contact);
  results.pressure.ram_reaction = problem.driven_force(system, u) / height;
  results.pressure.power_balance =
      (results.power.plastic_dissipation + results.power.friction) / (speed * height);
  results.pressure.total_power = results.power.total() / (speed * height);
  results.pressure.mean_hydrostatic_near_ram =
      mean_pressure_of_cells_at(problem, u, mesh::BoundaryLabel::Rear);
  results.fields = nodal_fields(problem, u, contact);
  results.max_equivalent_strain_rate = results.fields.cell_equivalent_strain_rate.maxCoeff();
  results.max_equivalent_strain_rate = std::max(results.max_equivalent_strain_rate,
                                                results.fields.equivalent_strain_rate.maxCoeff());
  results.contact = contact_profile(problem, contact);
  contact_zones(problem, contact, results.container_zones, results.die_zones);
  results.exit = exit_flow(problem, u);
}

template void evaluate_results<2>(const assembly::FormingProblem<2>&, const VectorX&, Results&,
                                  const assembly::FrictionMultipliers<2>*, Real);
template void evaluate_results<3>(const assembly::FormingProblem<3>&, const VectorX&, Results&,
                                  const assembly::FrictionMultipliers<3>*, Real);

} // namespace formflow::post
