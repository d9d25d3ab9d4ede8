// SPDX-License-Identifier: MIT
// Binning of the equivalent strain rate by distance from a corner.
#include "formflow/post/corner_profile.hpp"

#include "formflow/core/error.hpp"
#include "formflow/physics/kinematics.hpp"

#include <cmath>

namespace formflow::post {

template <int dim>
CornerProfile corner_profile(const assembly::FormingProblem<dim>& problem, const VectorX& u,
                             const Point<dim>& corner, Real r_min, Real r_max,
                             int bins_per_decade) {
  FF_ASSERT(r_min > 0 && r_max > r_min && bins_per_decade > 0, "corner profile range");
  const int n_bins =
      static_cast<int>(std::ceil(std::log10(r_max / r_min) * bins_per_decade - 1e-9));
  std::vector<Real> area(n_bins, 0.0), integral(n_bins, 0.0), largest(n_bins, 0.0);
  const auto& mesh = problem.discretisation().mesh();
  fem::CellValues<dim> values(mesh.cell_type(), problem.discretisation().full_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    problem.discretisation().gather(cell, &u, coordinates, velocities);
    values.reinit(coordinates);
    for (int q = 0; q < values.n_points(); ++q) {
      const Real distance = (values.point(q) - corner).norm();
      if (distance < r_min || distance >= r_max) continue;
      const int bin = static_cast<int>(std::floor(std::log10(distance / r_min) * bins_per_decade));
      if (bin < 0 || bin >= n_bins) continue;
      const Real rate = physics::equivalent_strain_rate(physics::strain_rate<dim>(
          physics::velocity_gradient<dim>(velocities, values.gradients(q))));
      area[bin] += values.JxW(q);
      integral[bin] += rate * values.JxW(q);
      largest[bin] = std::max(largest[bin], rate);
    }
  }
  CornerProfile profile;
  for (int bin = 0; bin < n_bins; ++bin) {
    if (area[bin] <= 0) continue;
    profile.radius.push_back(r_min * std::pow(10.0, (bin + 0.5) / bins_per_decade));
    profile.mean_rate.push_back(integral[bin] / area[bin]);
    profile.max_rate.push_back(largest[bin]);
  }
  return profile;
}

template CornerProfile corner_profile<2>(const assembly::FormingProblem<2>&, const VectorX&,
                                         const Point<2>&, Real, Real, int);
template CornerProfile corner_profile<3>(const assembly::FormingProblem<3>&, const VectorX&,
                                         const Point<3>&, Real, Real, int);

} // namespace formflow::post
