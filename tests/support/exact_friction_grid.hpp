// SPDX-License-Identifier: MIT
// The grid of issue 16 for exact Coulomb friction: ram condition × mesh size × μ ×
// element/rule × symmetry, each case solved with the exact law and with the paper's
// regularisation, and what a case must show.
#pragma once

#include "formflow/app/simulation.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace formflow::testing {

/// One case of the grid (mesh II's channel, friction on container and die, local τ_f).
struct FrictionGridCase {
  physics::RamCondition ram = physics::RamCondition::Sliding;
  double size = 1.0; ///< mesh.size h
  double mu = 0.1;
  fem::ElementKind element = fem::ElementKind::Q2;
  int volumetric_points = 2; ///< Q2 2×2 or Q1 1×1
  physics::Symmetry symmetry = physics::Symmetry::Plane;
  /// The semismooth Newton, the exact law's default (friction.stick = "auto": exact stick
  /// on nodal contact points; the regularised law on nodal points too, so that the loads
  /// compare on one discretisation). false: the augmented loop on face Gauss points
  /// (friction.stick = "augmented", the path before session 9).
  bool exact_stick = false;
};

inline std::string grid_case_name(const FrictionGridCase& c) {
  std::string name = fmt::format(
      "{}_h{}_mu{}_{}_{}x{}_{}", c.ram == physics::RamCondition::Sliding ? "sliding" : "sticking",
      c.size, c.mu, c.element == fem::ElementKind::Q1 ? "Q1" : "Q2", c.volumetric_points,
      c.volumetric_points, c.symmetry == physics::Symmetry::Plane ? "plane" : "axi");
  if (c.exact_stick) name += "_nodes_exact_stick";
  std::replace(name.begin(), name.end(), '.', 'p');
  return name;
}

/// The case with the exact law (regularization = "none") or the paper's d_T = 1e-6.
inline io::Case grid_case(const FrictionGridCase& c, bool exact, double tolerance) {
  io::Case case_;
  case_.solver.load_error = solvers::LoadErrorMethod::None; // not checked here; costs runs
  case_.process.ram = c.ram;
  case_.mesh.size = c.size;
  case_.friction.mu = c.mu;
  case_.element = c.element;
  case_.volumetric_points = c.volumetric_points;
  case_.symmetry = c.symmetry;
  case_.friction.regularization =
      exact ? physics::FrictionRegularization::None : physics::FrictionRegularization::Regularized;
  case_.solver.tolerance = tolerance;
  case_.solver.max_iterations = 200; // the setting: a stall or a tail shows as > 25
  // The exact law's default resolves to exact stick on nodes (io/problem_shape.hpp).
  if (c.exact_stick && !exact) case_.contact.normals = assembly::ContactNormals::Nodes;
  if (!c.exact_stick) case_.friction_stick = io::StickEnforcement::Augmented;
  return case_;
}

/// Newton iterations of a run, coarse levels included (multiplier updates happen
/// inside them: one per iteration).
inline int total_iterations(const post::Results& results) {
  return results.iterations +
         std::accumulate(results.coarse_iterations.begin(), results.coarse_iterations.end(), 0);
}

/// The bound: every case of the grid converges within 25 iterations.
inline constexpr int max_grid_iterations = 25;

/// How far the regularised law's load (d_T = 1e-6) may lie from the exact law's `exact`
/// (both solved to `tolerance`): the regularised friction functional exceeds the exact
/// one by at most d_T ∫τ_f dΓ ≤ d_T μ max σ_N |Γ3| (√(s² + d_T²) − s ≤ d_T), so for a
/// fixed τ_f the minimal powers, hence u⁰ H p, differ by at most that (for the nonlocal
/// law an estimate, the same at τ_f of the solution); plus 20 δ p per solve.
inline double regularisation_bound(const FrictionGridCase& c, const post::Results& exact,
                                   double tolerance) {
  double max_pressure = 0.0;
  for (const post::ContactSample& sample : exact.contact)
    max_pressure = std::max(max_pressure, sample.contact_pressure);
  const double contact_length = exact.container_zones.length + exact.die_zones.length;
  const io::Case reference = grid_case(c, false, tolerance);
  // H = the ram height R. Axisymmetric, Γ3's measure carries the radius (r dΓ), and so
  // does the true driven measure ∫_Γ1 r dr = ½ R² ≥ R: dividing by R over-estimates.
  return reference.friction.d_t * c.mu * max_pressure * contact_length /
             (reference.process.speed * reference.mesh.geometry.entry_half_height) +
         2 * 20 * tolerance * exact.pressure.ram_reaction;
}

/// Checks one case: the exact law converges to `tolerance` (within the bound of 25
/// iterations when `bounded`), its Coulomb residual is below it, and (with
/// `compare_regularised`) its load agrees with the regularised law's at d_T = 1e-6.
///
/// Iteration error: an iterate stopped at relative change δ is within ≈ 20 δ of the
/// fixed point (tests/verification/test_exact_friction.cpp; measured on the grid's
/// axisymmetric Q2 h = 0.25, μ = 0.5: 2.7 δ for the exact law, 1.1 δ regularised).
///
/// Load bound against the regularised law, both solved to δ_ref = 1e-8 so that the
/// comparison is not iteration error: regularisation_bound.
inline void check_grid_case(const FrictionGridCase& c, double tolerance, bool compare_regularised,
                            bool bounded = true) {
  SCOPED_TRACE(grid_case_name(c));
  const post::Results exact = app::simulate(grid_case(c, true, tolerance)).results;
  ASSERT_TRUE(exact.converged()) << solvers::stop_reason_name(exact.stop_reason) << " after "
                                 << total_iterations(exact) << " iterations";
  if (bounded) {
    EXPECT_LE(total_iterations(exact), max_grid_iterations);
  }
  // The default path is the semismooth Newton; exact_stick = false asks the old one.
  EXPECT_EQ(exact.method.find("semismooth newton") == 0, c.exact_stick) << exact.method;
  EXPECT_LT(exact.augmentation.friction_residual, tolerance);
  EXPECT_LT(exact.augmentation.power_residual, tolerance);
  const double p = exact.pressure.ram_reaction;
  // Reaction = total power in balance: u⁰ Σ_driven f = u·f(u) − u_f·R_f, and the stop
  // rule asks |u_f·R_f| < δ u⁰ Σ_driven f (solvers/power_residual.hpp), so they agree to
  // δ p (20 δ p as for the iteration error). (Before that rule, 12 axisymmetric cases with a stick
  // zone at the ram stopped out of balance: docs/friction.md "Reaction and total power".)
  EXPECT_NEAR(p, exact.pressure.total_power, 20 * tolerance * p);
  if (!compare_regularised) return;
  constexpr double reference_tolerance = 1e-8;
  const post::Results tight = app::simulate(grid_case(c, true, reference_tolerance)).results;
  const post::Results regularised = app::simulate(grid_case(c, false, reference_tolerance)).results;
  ASSERT_TRUE(tight.converged());
  ASSERT_TRUE(regularised.converged());
  const double p_tight = tight.pressure.ram_reaction;
  EXPECT_NEAR(p, p_tight, 20 * tolerance * p_tight);
  EXPECT_NEAR(regularised.pressure.ram_reaction, p_tight,
              regularisation_bound(c, tight, reference_tolerance));
}

} // namespace formflow::testing
