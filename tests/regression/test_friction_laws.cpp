// SPDX-License-Identifier: MIT
// The Tresca and hybrid friction thresholds (issue 13): friction = threshold ×
// enforcement, each threshold with both enforcements and both methods, checked
// against bounds that follow from the variational principle, not against numbers.
#include "formflow/app/simulation.hpp"
#include "formflow/io/case.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace formflow {
namespace {

constexpr double kTolerance = 1e-8; // δ: the runs below are compared far below 1e-4

/// The paper's mesh II with a sticking ram (SPEC §4) and the given edits.
post::Results solve(std::vector<io::Override> edits) {
  edits.insert(edits.begin(), {{"process.ram", "sticking"},
                               {"solver.tolerance", "1e-8"},
                               {"solver.max_iterations", "3000"},
                               {"solver.load_error", "none"}}); // not checked here; costs runs
  const post::Results results = app::simulate(io::load_case("", edits)).results;
  EXPECT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  return results;
}

/// Shear yield stress of a rigid billet, k = σ_p(rate1)/√3, for the default law.
double rigid_shear_yield() {
  const io::Case defaults = io::load_case("", {});
  return defaults.material.yield_stress(defaults.material.rate1) / std::sqrt(3.0);
}

/// ∫ |u_T| ds over the container wall (part 0) from the Γ3 samples' quadrature
/// weights: the samples are ordered by arc length, so the trapezoid rule over them.
double container_slip_integral(const post::Results& results) {
  double integral = 0.0;
  const auto& samples = results.contact;
  for (std::size_t k = 1; k < samples.size(); ++k)
    if (samples[k].part == 0 && samples[k - 1].part == 0)
      integral += 0.5 * (samples[k].slip_velocity + samples[k - 1].slip_velocity) *
                  (samples[k].arc_length - samples[k - 1].arc_length);
  return integral;
}

TEST(TrescaFriction, ZeroFactorIsTheFrictionlessProblemExactly) {
  const post::Results frictionless = solve({});
  const post::Results tresca =
      solve({{"friction.law", "tresca"}, {"friction.m", "0"}, {"friction.on", "[\"container\"]"}});
  EXPECT_EQ(tresca.pressure.ram_reaction, frictionless.pressure.ram_reaction);
  EXPECT_EQ(tresca.iterations, frictionless.iterations);
}

TEST(TrescaFriction, LoadRisesWithTheFactorBelowTheRigidSlidingBound) {
  const post::Results frictionless = solve({});
  const double p0 = frictionless.pressure.ram_reaction;
  const double k = rigid_shear_yield();
  const double height = 10.0; // the billet's half height H = entry_half_height
  // Upper-bound theorem: the frictionless solution u⁰ is admissible for the problem
  // with friction, so p_m ≤ p_0 + m k ∫_container |u⁰_T| ds / (u⁰ H) (u⁰ = 1). The
  // bound holds for the dissipation potential; the reaction is the power, which
  // exceeds it by the rate sensitivity α (σ_p ∝ ε̄̇^α: power = (1 + α) potential)
  // and by the penalty terms' power (1/d) ε̇_V², (1/d_N) u_N² (twice their potential).
  // Those margins are the measured penalty powers of u⁰ plus α p_0.
  const double slip = container_slip_integral(frictionless);
  const double alpha =
      io::load_case("", {}).material.parameters_of<physics::PiecewisePower>().alpha;
  const double margin =
      alpha * p0 +
      (frictionless.power.volumetric_penalty + frictionless.power.contact_penalty) / height;
  ASSERT_GT(slip, 0.0);
  double previous = p0;
  for (const double m : {0.25, 0.5, 1.0}) {
    const post::Results run = solve({{"friction.law", "tresca"},
                                     {"friction.m", std::to_string(m)},
                                     {"friction.on", "[\"container\"]"}});
    const double p = run.pressure.ram_reaction;
    EXPECT_GT(p, previous) << "m = " << m;
    EXPECT_LE(p - p0, m * k * slip / height + margin) << "m = " << m;
    // The rigid-billet estimate L_slide = 5 (the billet sliding over the
    // container's first half at the ram speed, a dead-metal zone holding the rest) is
    // not a bound: the frictionless wall slip decays gradually into the dead zone and
    // integrates to ∫|u⁰_T| ≈ 5.5 on mesh II, and the measured rise exceeds m k 5/H by
    // about 2 % (docs/friction.md, "Tresca and hybrid thresholds").
    std::printf("m = %.2f: p − p0 = %.6f, m k ∫|u⁰_T|/H = %.6f, m k 5/H = %.6f\n", m, p - p0,
                m * k * slip / height, m * k * 5.0 / height);
    previous = p;
  }
}

/// Smallest and largest of μσ̄_N/(m k) over the container's contact samples (local
/// pressure: friction.radius = 0, so σ̄_N = −σ_N), with k of the rigid billet.
std::pair<double, double> coulomb_over_tresca(const post::Results& results, double mu, double m) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  const double k = rigid_shear_yield();
  for (const post::ContactSample& sample : results.contact) {
    if (sample.part != 0) continue;
    const double ratio = mu * std::max(sample.contact_pressure, 0.0) / (m * k);
    low = std::min(low, ratio);
    high = std::max(high, ratio);
  }
  return {low, high};
}

TEST(HybridFriction, EqualsCoulombBelowTheCapAndTrescaAboveIt) {
  const std::vector<io::Override> container = {{"friction.on", "[\"container\"]"}};
  auto with = [&](std::vector<io::Override> edits) {
    edits.insert(edits.end(), container.begin(), container.end());
    return solve(edits);
  };
  // μσ̄_N < m k everywhere: the cap never acts.
  const post::Results coulomb = with({{"friction.law", "coulomb"}, {"friction.mu", "0.05"}});
  const post::Results low =
      with({{"friction.law", "hybrid"}, {"friction.mu", "0.05"}, {"friction.m", "1"}});
  ASSERT_LT(coulomb_over_tresca(coulomb, 0.05, 1.0).second, 1.0);
  // Both converged to δ = 1e-8 on the same discrete problem: equal to a few δ.
  EXPECT_NEAR(low.pressure.ram_reaction, coulomb.pressure.ram_reaction,
              10 * kTolerance * coulomb.pressure.ram_reaction);
  // μσ̄_N > m k everywhere: the cap always acts.
  const post::Results tresca = with({{"friction.law", "tresca"}, {"friction.m", "0.3"}});
  const post::Results high =
      with({{"friction.law", "hybrid"}, {"friction.mu", "10"}, {"friction.m", "0.3"}});
  ASSERT_GT(coulomb_over_tresca(tresca, 10.0, 0.3).first, 1.0);
  EXPECT_NEAR(high.pressure.ram_reaction, tresca.pressure.ram_reaction,
              10 * kTolerance * tresca.pressure.ram_reaction);
}

/// Every threshold runs with both enforcements and both methods.
class ThresholdTimesEnforcement
    : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(ThresholdTimesEnforcement, NewtonAndSecantAgree) {
  const auto [law, regularization] = GetParam();
  const std::vector<io::Override> edits = {{"friction.law", law},
                                           {"friction.mu", "0.1"},
                                           {"friction.m", "0.3"},
                                           {"friction.regularization", regularization},
                                           {"mesh.size", "2.5"}};
  std::vector<io::Override> newton = edits, secant = edits;
  // Both on nodal contact points: the exact law's Newton default is the semismooth
  // Newton there (friction.stick = "auto"), and the secant loop's referee must see the
  // same discretisation of the contact terms.
  if (std::string(regularization) == "none")
    for (auto* run : {&newton, &secant}) run->emplace_back("contact.normals", "nodes");
  newton.emplace_back("solver.method", "newton");
  secant.emplace_back("solver.method", "secant");
  const post::Results by_newton = solve(newton), by_secant = solve(secant);
  // The secant loop contracts at ρ ≲ 0.95: stopped at change δ it is within ≈ 20 δ.
  EXPECT_NEAR(by_newton.pressure.ram_reaction, by_secant.pressure.ram_reaction,
              20 * kTolerance * by_secant.pressure.ram_reaction);
  EXPECT_GT(by_newton.power.friction, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Laws, ThresholdTimesEnforcement,
                         ::testing::Combine(::testing::Values("coulomb", "tresca", "hybrid"),
                                            ::testing::Values("regularized", "none")),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param)) + "_" +
                                  std::get<1>(info.param);
                         });

} // namespace
} // namespace formflow
