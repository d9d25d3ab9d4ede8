// SPDX-License-Identifier: MIT
// Powers of the discrete terms and the mean hydrostatic pressure near the ram (in a
// distributed run: over the rank's own cells, summed over the ranks).
#include "formflow/physics/kinematics.hpp"
#include "formflow/post/post_process.hpp"

#include <array>

namespace formflow::post {

template <int dim>
PowerTerms compute_powers(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                          const std::vector<assembly::ContactPoint<dim>>& contact) {
  return problem.powers(u, contact); // a sum over the weak-form terms
}

template <int dim>
Real mean_pressure_of_cells_at(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                               mesh::BoundaryLabel label) {
  const auto& mesh = problem.discretisation().mesh();
  fem::CellValues<dim> values(mesh.cell_type(), problem.discretisation().volumetric_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  std::vector<bool> counted(mesh.n_cells(), false);
  const std::vector<assembly::CellPressure> pressures = problem.cell_pressures(u);
  Real integral = 0.0, area = 0.0;
  // A distributed run: the rank's own cells here, the sums over the ranks below.
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != label || counted[facet.cell] ||
        !problem.discretisation().assembles(facet.cell))
      continue;
    counted[facet.cell] = true;
    problem.discretisation().gather(facet.cell, nullptr, coordinates, velocities);
    problem.discretisation().reinit(values, coordinates);
    integral -= pressures[facet.cell].integral; // −σ_H dx
    for (int q = 0; q < values.n_points(); ++q) area += values.JxW(q);
  }
  if (const auto& distribution = problem.discretisation().distribution();
      distribution.distributed()) {
    std::array<Real, 2> sums{integral, area};
    distribution.sum_over_ranks(sums);
    integral = sums[0], area = sums[1];
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
