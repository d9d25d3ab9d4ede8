// SPDX-License-Identifier: MIT
// Temperature error norms by a higher-order Gauss rule.
#include "formflow/post/temperature_error_norms.hpp"
#include "formflow/fem/reference_element.hpp"

#include "formflow/post/error_norms.hpp"

#include <cmath>

namespace formflow::post {

template <int dim>
TemperatureErrorNorms temperature_error_norms(const assembly::Discretisation<dim>& discretisation,
                                              const VectorX& T_h,
                                              const ExactTemperature<dim>& exact) {
  const auto& mesh = discretisation.mesh();
  fem::CellValues<dim> values(mesh.cell_type(),
                              fem::rule_of_points<dim>(mesh.cell_type(), error_quadrature_points));
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  Real l2_square = 0.0, h1_square = 0.0;
  VectorX local(mesh.nodes_per_cell());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    discretisation.gather(cell, nullptr, coordinates, unused);
    values.reinit(coordinates);
    for (int a = 0; a < local.size(); ++a) local[a] = T_h[mesh.cells(a, cell)];
    for (int q = 0; q < values.n_points(); ++q) {
      const Point<dim> x = values.point(q);
      const Real error = values.shape(q).dot(local) - exact.value(x);
      const Point<dim> gradient_error = values.gradients(q) * local - exact.gradient(x);
      l2_square += error * error * values.JxW(q);
      h1_square += gradient_error.squaredNorm() * values.JxW(q);
    }
  }
  return {std::sqrt(l2_square), std::sqrt(h1_square)};
}

template TemperatureErrorNorms temperature_error_norms<2>(const assembly::Discretisation<2>&,
                                                          const VectorX&,
                                                          const ExactTemperature<2>&);
template TemperatureErrorNorms temperature_error_norms<3>(const assembly::Discretisation<3>&,
                                                          const VectorX&,
                                                          const ExactTemperature<3>&);

} // namespace formflow::post
