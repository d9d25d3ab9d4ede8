// SPDX-License-Identifier: MIT
// Error norms of a nodal temperature against an exact one (coupled manufactured solution).
#pragma once

#include "formflow/assembly/discretisation.hpp"

#include <functional>

namespace formflow::post {

/// ‖T_h − T‖_L2 and |T_h − T|_H1 = ‖∇(T_h − T)‖_L2 over Ω.
struct TemperatureErrorNorms {
  Real l2 = 0.0;
  Real h1 = 0.0;
};

template <int dim> struct ExactTemperature {
  std::function<Real(const Point<dim>&)> value;
  std::function<Point<dim>(const Point<dim>&)> gradient;
};

/// The norms for T_h in the Lagrange space of the mesh's nodes (assembly/heat_problem.hpp),
/// by the Gauss rule of post/error_norms.hpp (error_quadrature_points per direction).
template <int dim>
TemperatureErrorNorms temperature_error_norms(const assembly::Discretisation<dim>& discretisation,
                                              const VectorX& T_h,
                                              const ExactTemperature<dim>& exact);

} // namespace formflow::post
