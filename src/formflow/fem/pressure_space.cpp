// SPDX-License-Identifier: MIT
// Pressure bases: reference monomials (discontinuous spaces) or vertex functions (Q1, P1).
#include "formflow/fem/pressure_space.hpp"

#include "formflow/fem/lagrange.hpp"

namespace formflow::fem {

template <int dim> int pressure_functions_per_cell(PressureSpace space) {
  switch (space) {
  case PressureSpace::P0: return 1;
  case PressureSpace::P1disc:
  case PressureSpace::P1: return dim + 1;
  case PressureSpace::Q1disc:
  case PressureSpace::Q1: return 1 << dim;
  }
  return 0;
}

template <int dim> VectorX tabulate_pressure(PressureSpace space, const Point<dim>& xi) {
  VectorX values(pressure_functions_per_cell<dim>(space));
  switch (space) {
  case PressureSpace::P0: values[0] = 1.0; break;
  case PressureSpace::P1disc:
    values[0] = 1.0;
    for (int i = 0; i < dim; ++i) values[i + 1] = xi[i];
    break;
  case PressureSpace::Q1disc:
    // Monomial ∏_{i ∈ bits(k)} ξ_i: 1, ξ, η, ξη (, ζ, ξζ, ηζ, ξηζ).
    for (int k = 0; k < values.size(); ++k) {
      values[k] = 1.0;
      for (int i = 0; i < dim; ++i)
        if (k & (1 << i)) values[k] *= xi[i];
    }
    break;
  case PressureSpace::Q1: {
    Eigen::Matrix<Real, dim, Eigen::Dynamic> unused;
    tabulate_shape<dim>(1, xi, values, unused);
    break;
  }
  case PressureSpace::P1:
    values[0] = 1.0;
    for (int i = 0; i < dim; ++i) {
      values[0] -= xi[i];
      values[i + 1] = xi[i];
    }
    break;
  }
  return values;
}

template int pressure_functions_per_cell<2>(PressureSpace);
template int pressure_functions_per_cell<3>(PressureSpace);
template VectorX tabulate_pressure<2>(PressureSpace, const Point<2>&);
template VectorX tabulate_pressure<3>(PressureSpace, const Point<3>&);

} // namespace formflow::fem
