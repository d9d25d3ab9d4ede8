// SPDX-License-Identifier: MIT
// Anderson acceleration of the paper's secant iteration (CHOLMOD, mesh II): the same
// fixed point within the stop's reach of δ, in fewer steps.
#include "regression/benchmark_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace formflow {
namespace {

constexpr Real anderson_run_delta = 1e-6; // solver.tolerance of the secant runs

post::Results paper_secant_run(Real mu, solvers::NonlinearAcceleration acceleration) {
  return testing::solve_benchmark([&](io::Case& c) {
    c.friction.mu = mu;
    c.solver.method = solvers::NonlinearMethod::Secant;
    c.solver.acceleration = acceleration;
    c.solver.tolerance = anderson_run_delta;
    c.solver.max_iterations = 2000;
  });
}

/// The contraction ρ of the secant map, read from the plain run's last two changes (its
/// tail contracts at a steady rate; an accelerated run's changes say nothing about ρ).
Real secant_contraction(const post::Results& plain) {
  const auto& history = plain.history;
  EXPECT_GE(history.size(), 2U);
  if (history.size() < 2) return 0.99;
  return std::min<Real>(0.99, history.back().relative_change /
                                  history[history.size() - 2].relative_change);
}

Real relative_load_gap(const post::Results& a, const post::Results& b) {
  return std::abs(a.pressure.ram_reaction - b.pressure.ram_reaction) /
         std::abs(b.pressure.ram_reaction);
}

class AndersonSecantRun : public ::testing::TestWithParam<Real> {};

/// Each run stops at an exact step whose change c < δ and returns that step's result
/// G(x), within ρ/(1 − ρ) c of the fixed point whatever x was (mixed or not); the loads
/// are taken to err as much as the velocities, relative. The two runs' loads then differ
/// by at most ρ/(1 − ρ) (c_plain + c_anderson), and Newton's (quadratic, its last change
/// bounds its distance) lies within ρ/(1 − ρ) c_anderson + its last change of the
/// accelerated one.
TEST_P(AndersonSecantRun, FewerStepsToTheSameFixedPoint) {
  const Real mu = GetParam();
  const post::Results plain = paper_secant_run(mu, solvers::NonlinearAcceleration::None);
  const post::Results anderson = paper_secant_run(mu, solvers::NonlinearAcceleration::Anderson);
  const post::Results newton = testing::solve_benchmark([&](io::Case& c) {
    c.friction.mu = mu;
    c.solver.tolerance = 1e-10;
  });
  ASSERT_TRUE(plain.converged());
  ASSERT_TRUE(anderson.converged());
  ASSERT_TRUE(newton.converged());
  const Real rho = secant_contraction(plain);
  const Real reach = rho / (1 - rho);
  const Real c_plain = plain.history.back().relative_change;
  const Real c_anderson = anderson.history.back().relative_change;
  std::cout << "μ = " << mu << ": secant steps " << plain.iterations << " plain, "
            << anderson.iterations << " Anderson (ρ = " << rho << "); load gap "
            << relative_load_gap(anderson, plain) << " (bound " << reach * (c_plain + c_anderson)
            << "), to Newton " << relative_load_gap(anderson, newton) << "\n";
  EXPECT_LT(anderson.iterations, plain.iterations);
  EXPECT_TRUE(std::any_of(anderson.history.begin(), anderson.history.end(),
                          [](const auto& record) { return record.mixed_columns > 0; }));
  EXPECT_LE(relative_load_gap(anderson, plain), reach * (c_plain + c_anderson));
  EXPECT_LE(relative_load_gap(anderson, newton),
            reach * c_anderson + newton.history.back().relative_change);
}

// The paper's mesh II without friction and with μ = 0.1 (regularised friction: the
// lagged slip velocity is part of the map that is mixed).
INSTANTIATE_TEST_SUITE_P(PaperMeshTwo, AndersonSecantRun, ::testing::Values(0.0, 0.1));

} // namespace
} // namespace formflow
