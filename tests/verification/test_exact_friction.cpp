// SPDX-License-Identifier: MIT
// Exact Coulomb friction (friction.regularization = "none") on the benchmark, mesh I:
// μ = 0 is the frictionless solution, the Coulomb conditions hold pointwise at the
// Γ3 quadrature points, the ram reaction equals the total discrete power, and the
// regularised solutions approach it as d_T → 0 at least as fast as √d_T (Thm 3.3).
// Each for both loops: the augmented Lagrangian around the secant iteration (the
// paper's method) and around Newton (solvers/augmented_newton.hpp).
#include "support/approx.hpp"
#include "support/friction_study.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace formflow::testing {
namespace {

constexpr double mesh_one = 10.0 / 6.0;

io::Case benchmark(double mu, double radius, physics::FrictionRegularization regularization,
                   solvers::NonlinearMethod method) {
  io::Case case_;
  case_.solver.method = method;
  case_.mesh.size = mesh_one;
  case_.friction.mu = mu;
  case_.friction.radius = radius;
  case_.friction.regularization = regularization;
  case_.solver.max_iterations = 20000;
  // Newton: the exact law's default is the semismooth Newton on nodal contact points
  // (friction.stick = "auto"); the regularised runs it is compared with take the same
  // points, so that both laws see one discretisation of the contact terms.
  if (method == solvers::NonlinearMethod::Newton)
    case_.contact.normals = assembly::ContactNormals::Nodes;
  return case_;
}

constexpr auto exact = physics::FrictionRegularization::None;
constexpr auto regularized = physics::FrictionRegularization::Regularized;
constexpr auto secant = solvers::NonlinearMethod::Secant;
constexpr auto newton = solvers::NonlinearMethod::Newton;

class ExactFriction : public ::testing::TestWithParam<solvers::NonlinearMethod> {};

TEST_P(ExactFriction, WithZeroCoefficientIsTheFrictionlessSolution) {
  const auto method = GetParam();
  const FrictionSolve frictionless = solve_friction_case(benchmark(0.0, 0.0, regularized, method));
  const FrictionSolve exact_zero = solve_friction_case(benchmark(0.0, 0.0, exact, method));
  ASSERT_TRUE(frictionless.converged());
  ASSERT_TRUE(exact_zero.converged());
  // τ_f = 0 makes the projection 0: no load, no penalty, the same equations. The
  // secant loops then do the same arithmetic (identical iterates), but Newton's
  // exact-friction loop orders it differently (its tangent and multiplier update
  // add zeros in other places), so its final iterate differs from the regularised
  // one by the forward error of the last solves, ≲ ε·κ(K) relative, and the
  // reaction (a sum of K u over the rear) by the same relative amount. κ = 1/rcond,
  // CHOLMOD's estimate at the solution (≈ 1.6e5 here, so the bound is ≈ 3.5e-11).
  // A fixed 1e-12 was round-off luck: ten OpenBLAS kernels gave 5e-16 to 1.4e-12 on
  // the reaction, Prescott and Barcelona above 1e-12 (docs/reliability.md): ≤ 0.04 ε·κ.
  const double round_off = std::numeric_limits<double>::epsilon() /
                           app::condition_at(*frictionless.problem, frictionless.velocity);
  EXPECT_LT(relative_velocity_difference(exact_zero.velocity, frictionless.velocity), round_off);
  EXPECT_EQ(exact_zero.iterations, frictionless.iterations);
  EXPECT_TRUE(approx(exact_zero.results.pressure.ram_reaction,
                     frictionless.results.pressure.ram_reaction, round_off));
  EXPECT_EQ(exact_zero.results.power.friction, 0.0);
  // Secant: one inner solve, then nothing to update. Newton: an update after
  // every iteration, each finding nothing to change.
  EXPECT_EQ(exact_zero.augmentations, method == secant ? 1 : exact_zero.iterations);
  EXPECT_EQ(exact_zero.multiplier_change, 0.0);
}

/// μ, mollifier radius, nonlinear loop.
using Variant = std::tuple<double, double, solvers::NonlinearMethod>;
class ExactCoulomb : public ::testing::TestWithParam<Variant> {};

TEST_P(ExactCoulomb, ConditionsHoldPointwiseAndReactionEqualsPower) {
  const auto [mu, radius, method] = GetParam();
  io::Case case_ = benchmark(mu, radius, exact, method);
  case_.solver.tolerance = 1e-7;
  const FrictionSolve solve = solve_friction_case(case_);
  ASSERT_TRUE(solve.converged());
  // Each loop's stop rule: the secant AL loop's multiplier change, Newton's Coulomb
  // residual (solvers/friction_residual.hpp); the pointwise checks below hold for both.
  EXPECT_LT(method == secant ? solve.multiplier_change : solve.friction_residual,
            case_.solver.tolerance);

  const Real speed = case_.process.speed;
  int sticking = 0, slipping = 0;
  for (const auto& point : solve.contact()) {
    const Real tau = point.friction_threshold;
    const Real traction = point.friction_traction.norm();
    const Real slip = point.tangential_velocity.norm();
    ASSERT_GT(tau, 0.0) << "Γ3 is in compression on the benchmark";
    // |λ_T| ≤ τ_f (rounding only: the traction is a projection onto the disc).
    EXPECT_LE(traction, tau * (1 + 1e-12));
    if (traction < tau * (1 - 1e-6)) {
      // Inside the disc: stick. The slip left is the multiplier change / r, far
      // below the paper's d_T = 1e-6 u⁰ that the regularised law would leave.
      ++sticking;
      EXPECT_LT(slip, 1e-6 * speed) << "sticking point slips at x = " << point.position.transpose();
    } else if (slip > 1e-5 * speed) {
      // On the circle and slipping: σ_T = −λ_T opposes u_T (cosine −1 to 1e-6).
      ++slipping;
      EXPECT_GT(point.friction_traction.dot(point.tangential_velocity),
                (1 - 1e-6) * traction * slip)
          << "at x = " << point.position.transpose();
    }
  }
  // The benchmark has both zones: dead metal sticks in the corner (10, 10), the
  // die face and the container wall near the ram slip.
  EXPECT_GT(sticking, 0);
  EXPECT_GT(slipping, 0);

  // Load consistency (as for the regularised law): at the fixed point uᵀK(u)u − uᵀF
  // = u⁰·reaction, with the friction power ∫λ_T·u_T dΓ in the total. An iterate
  // stopped at relative change δ is within ≈ 20 δ of the fixed point.
  const auto& pressure = solve.results.pressure;
  EXPECT_GT(solve.results.power.friction, 0.0);
  EXPECT_LT(std::abs(pressure.ram_reaction - pressure.total_power) / pressure.ram_reaction,
            20 * case_.solver.tolerance);
}

std::string loop_name(solvers::NonlinearMethod method) {
  return method == secant ? "Secant" : "Newton";
}

std::string variant_name(const ::testing::TestParamInfo<Variant>& info) {
  const double mu = std::get<0>(info.param), radius = std::get<1>(info.param);
  return std::string(mu == 0.1 ? "Mu01" : "Mu02") + (radius == 0.0 ? "Local" : "Nonlocal") +
         loop_name(std::get<2>(info.param));
}

std::string method_name(const ::testing::TestParamInfo<solvers::NonlinearMethod>& info) {
  return loop_name(info.param);
}

INSTANTIATE_TEST_SUITE_P(BenchmarkMeshOne, ExactCoulomb,
                         ::testing::Combine(::testing::Values(0.1, 0.2),
                                            ::testing::Values(0.0, mesh_one),
                                            ::testing::Values(secant, newton)),
                         variant_name);

TEST_P(ExactFriction, RegularisedSolutionsConvergeAtLeastLikeSquareRootOfDT) {
  // Theorem 3.3: ‖u − u_dT‖ ≤ C √d_T. The discrete error measure is the relative
  // l² norm of the nodal velocities; the pressure difference is checked alongside.
  // Both solves are iterated far below the smallest difference (δ = 1e-10).
  const auto method = GetParam();
  const double mu = 0.2;
  io::Case reference_case = benchmark(mu, 0.0, exact, method);
  reference_case.solver.tolerance = 1e-10;
  const FrictionSolve reference = solve_friction_case(reference_case);
  ASSERT_TRUE(reference.converged());

  std::vector<double> d_t = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6}, velocity_error, pressure_error;
  for (double value : d_t) {
    io::Case case_ = benchmark(mu, 0.0, regularized, method);
    case_.friction.d_t = value * case_.process.speed;
    case_.solver.tolerance = 1e-10;
    const FrictionSolve solve = solve_friction_case(case_);
    ASSERT_TRUE(solve.converged()) << "d_T = " << value;
    velocity_error.push_back(relative_velocity_difference(solve.velocity, reference.velocity));
    pressure_error.push_back(
        std::abs(solve.results.pressure.ram_reaction - reference.results.pressure.ram_reaction));
    std::cout << "d_T = " << value << ": velocity " << velocity_error.back() << ", pressure "
              << pressure_error.back() << ", iterations " << solve.iterations << "\n";
  }
  // The theorem's quantity: the observed rate between the two finest d_T (observed
  // here ≈ 0.9, i.e. nearly linear, better than the guaranteed ½).
  const std::size_t last = d_t.size() - 1;
  const double velocity_rate = std::log10(velocity_error[last - 1] / velocity_error[last]);
  EXPECT_GE(velocity_rate, 0.5 - 0.15);
  for (std::size_t k = 1; k < d_t.size(); ++k) EXPECT_LT(velocity_error[k], velocity_error[k - 1]);
  // The pressure is a functional of u, so |p_dT − p| ≤ C ‖u_dT − u‖: it must stay
  // under the √d_T envelope drawn from the coarsest rung. Its ratio between two
  // rungs is no rate: p_dT − p changes sign between d_T = 1e-5 and 1e-6 on this
  // mesh (−9.5e-8, then +4.6e-8; +7.8e-9 at 1e-7), so that ratio is only 0.33.
  for (std::size_t k = 1; k < d_t.size(); ++k)
    EXPECT_LE(pressure_error[k], pressure_error[0] * std::sqrt(d_t[k] / d_t[0]))
        << "d_T = " << d_t[k];
}

INSTANTIATE_TEST_SUITE_P(BothLoops, ExactFriction, ::testing::Values(secant, newton), method_name);

} // namespace
} // namespace formflow::testing
