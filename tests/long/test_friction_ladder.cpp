// SPDX-License-Identifier: MIT
// Exact friction on the paper's benchmark itself (Q2, 2×2 rule, mesh II): it
// converges at the paper's δ = 1e-4 for μ = 0.1, 0.2 with the local and the
// mollified pressure, satisfies the Coulomb conditions, and the regularised
// solutions approach it as d_T → 0 at least like √d_T (Theorem 3.3). Minutes.
// Both loops: the secant one (docs/friction.md's tables) and Newton.
#include "support/approx.hpp"
#include "support/friction_study.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

namespace formflow::testing {
namespace {

/// μ, mollifier radius (0 = local, 1 = one cell of mesh II), nonlinear loop.
using Variant = std::tuple<double, double, solvers::NonlinearMethod>;
class FrictionLadder : public ::testing::TestWithParam<Variant> {};

io::Case benchmark(double mu, double radius, physics::FrictionRegularization regularization,
                   solvers::NonlinearMethod method) {
  io::Case case_; // defaults: Q2, 2×2 volumetric rule, mesh II, friction on container and die
  case_.friction.mu = mu;
  case_.friction.radius = radius;
  case_.friction.regularization = regularization;
  case_.solver.max_iterations = 100000;
  // The secant path's numbers are docs/friction.md's tables (bench/friction_table.py).
  case_.solver.method = method;
  // Newton: the exact law's default is the semismooth Newton on nodal contact points
  // (friction.stick = "auto"); the regularised runs it is compared with take the same
  // points, so that both laws see one discretisation of the contact terms.
  if (method == solvers::NonlinearMethod::Newton)
    case_.contact.normals = assembly::ContactNormals::Nodes;
  return case_;
}

TEST_P(FrictionLadder, ExactConvergesAtThePapersToleranceWithStickAndSlip) {
  const auto [mu, radius, method] = GetParam();
  const FrictionSolve solve =
      solve_friction_case(benchmark(mu, radius, physics::FrictionRegularization::None, method));
  ASSERT_TRUE(solve.converged());
  // The secant iteration alone needs ≈ 60 here; the multiplier updates add ≈ 30–45
  // single secant steps. Newton: 16–24 (docs/friction.md "Cost"). Bounds that
  // would catch a loop that stalls.
  EXPECT_LT(solve.iterations, method == solvers::NonlinearMethod::Newton ? 30 : 200);
  const auto& zones = solve.results.die_zones;
  EXPECT_GT(zones.stick_length, 0.0);
  EXPECT_GT(zones.slip_length(), 0.0);
  const auto& pressure = solve.results.pressure;
  EXPECT_LT(std::abs(pressure.ram_reaction - pressure.total_power) / pressure.ram_reaction,
            20 * 1e-4);
}

TEST_P(FrictionLadder, RegularisedApproachesExactAtLeastLikeSquareRootOfDT) {
  const auto [mu, radius, method] = GetParam();
  io::Case exact_case = benchmark(mu, radius, physics::FrictionRegularization::None, method);
  exact_case.solver.tolerance = 1e-9;
  const FrictionSolve reference = solve_friction_case(exact_case);
  ASSERT_TRUE(reference.converged());
  const std::vector<double> d_t = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  std::vector<double> velocity_error, pressure_error;
  for (double value : d_t) {
    io::Case case_ = benchmark(mu, radius, physics::FrictionRegularization::Regularized, method);
    case_.friction.d_t = value * case_.process.speed;
    case_.solver.tolerance = 1e-9;
    const FrictionSolve solve = solve_friction_case(case_);
    ASSERT_TRUE(solve.converged()) << "d_T = " << value;
    velocity_error.push_back(relative_velocity_difference(solve.velocity, reference.velocity));
    pressure_error.push_back(
        std::abs(solve.results.pressure.ram_reaction - reference.results.pressure.ram_reaction));
    std::cout << "mu " << mu << " h " << radius << " d_T " << value << ": velocity "
              << velocity_error.back() << " pressure " << pressure_error.back() << "\n";
  }
  // Relative l² of nodal velocities between the two finest d_T (Theorem 3.3: ≥ ½).
  const std::size_t last = d_t.size() - 1;
  EXPECT_GE(std::log10(velocity_error[last - 1] / velocity_error[last]), 0.5 - 0.15);
  // The pressure difference may change sign along the ladder (see
  // tests/verification/test_exact_friction.cpp): it must stay under the √d_T envelope.
  for (std::size_t k = 1; k < d_t.size(); ++k)
    EXPECT_LE(pressure_error[k], pressure_error[0] * std::sqrt(d_t[k] / d_t[0]))
        << "d_T = " << d_t[k];
}

INSTANTIATE_TEST_SUITE_P(
    MeshTwo, FrictionLadder,
    ::testing::Combine(::testing::Values(0.1, 0.2), ::testing::Values(0.0, 1.0),
                       ::testing::Values(solvers::NonlinearMethod::Secant,
                                         solvers::NonlinearMethod::Newton)),
    [](const ::testing::TestParamInfo<Variant>& info) {
      return std::string(std::get<0>(info.param) == 0.1 ? "Mu01" : "Mu02") +
             (std::get<1>(info.param) == 0.0 ? "Local" : "Nonlocal") +
             (std::get<2>(info.param) == solvers::NonlinearMethod::Newton ? "Newton" : "Secant");
    });

} // namespace
} // namespace formflow::testing
