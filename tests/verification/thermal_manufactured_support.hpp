// SPDX-License-Identifier: MIT
// The coupled manufactured case of hot forming and its observed orders (shared by the
// fast test and the long ladder).
#pragma once

#include "formflow/app/simulation.hpp"
#include "formflow/physics/flow_laws/sellars_tegart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace formflow::testing {

/// Aluminium-like numbers in MPa, mm, s, °C: ρc = 2.43 MPa/K, κ = 0.5 N/(s·K) (a global
/// Péclet number ρc|u|L/κ ≈ 5, so convection and conduction both matter), the AA6063
/// law from 400 °C to 490 °C. The tolerances (secant 1e-9, coupling 1e-8) sit four orders
/// and more below the discretisation errors measured (velocity ≥ 5e-5, T ≥ 7e-4 of 90 K
/// rise on the finest meshes here), so the errors are the discretisation's alone.
inline io::Case coupled_case(fem::ElementKind element, Real size) {
  io::Case case_;
  case_.manufactured = physics::ManufacturedSolution::Smooth;
  case_.element = element;
  case_.mesh.size = size;
  case_.volumetric_points = element == fem::ElementKind::Q1 ? 1 : 2;
  case_.material.law = physics::SellarsTegart::name;
  case_.thermal.enabled = true;
  case_.thermal.billet_temperature = 400.0;
  case_.thermal.density = 2.7e-9;
  case_.thermal.heat_capacity = 9.0e8;
  case_.thermal.conductivity = 0.5;
  case_.thermal.coupling_tolerance = 1e-8;
  case_.solver.tolerance = 1e-9;
  case_.solver.max_iterations = 2000;
  return case_;
}

struct Errors {
  Real velocity_v, velocity_l2, temperature_h1, temperature_l2;
};

inline Errors errors_of(fem::ElementKind element, Real size) {
  const app::Simulation simulation = app::simulate(coupled_case(element, size));
  EXPECT_TRUE(simulation.results.converged())
      << solvers::stop_reason_name(simulation.results.stop_reason);
  EXPECT_TRUE(simulation.results.thermal.coupling_converged);
  return {simulation.errors->v_norm, simulation.errors->l2, simulation.temperature_errors->h1,
          simulation.temperature_errors->l2};
}

inline Real order(Real coarse, Real fine) {
  return std::log2(coarse / fine);
}

/// Velocity ‖ε̇(u − u_h)‖ (the V norm, an H¹ seminorm) at order l, ‖u − u_h‖_L2 at l + 1,
/// temperature |T − T_h|_H1 at l and ‖T − T_h‖_L2 at l + 1, within 0.15 (the issue's
/// criterion) from `coarse` to `fine`.
inline void expect_orders(int l, const Errors& coarse, const Errors& fine) {
  EXPECT_NEAR(order(coarse.velocity_v, fine.velocity_v), l, 0.15);
  EXPECT_NEAR(order(coarse.velocity_l2, fine.velocity_l2), l + 1, 0.15);
  EXPECT_NEAR(order(coarse.temperature_h1, fine.temperature_h1), l, 0.15);
  EXPECT_NEAR(order(coarse.temperature_l2, fine.temperature_l2), l + 1, 0.15);
}

} // namespace formflow::testing
