// SPDX-License-Identifier: MIT
// Volumetric locking of fully integrated Q1, and friction never lowering the load.
#include "regression/benchmark_support.hpp"

#include <gtest/gtest.h>

namespace formflow {
namespace {

double pressure(fem::ElementKind element, int rule, double d, double mu = 0.0) {
  const post::Results results = testing::solve_benchmark([&](io::Case& c) {
    c.element = element;
    c.volumetric_points = rule;
    c.penalty.d = d;
    c.friction.mu = mu;
  });
  EXPECT_TRUE(results.converged());
  return results.pressure.ram_reaction;
}

TEST(Locking, FullyIntegratedQ1LocksAndWorsensAsPenaltyGrows) {
  // Q1 with the complete 2×2 volumetric rule imposes two to four divergence
  // constraints per cell on two dofs per node: the discrete incompressible
  // space collapses and the load scales with 1/d instead of converging.
  const double locked = pressure(fem::ElementKind::Q1, 2, 1e-3);
  const double reduced = pressure(fem::ElementKind::Q1, 1, 1e-3);
  const double quadratic = pressure(fem::ElementKind::Q2, 2, 1e-3);
  EXPECT_GT(locked, 1.5 * reduced);
  EXPECT_GT(locked, 1.5 * quadratic);
  const double more_locked = pressure(fem::ElementKind::Q1, 2, 1e-4);
  EXPECT_GT(more_locked, 2.0 * locked);
  // The reduced rule (≡ {Q1, P0, P1}) does not lock: tenfold d barely moves it.
  EXPECT_LT(std::abs(pressure(fem::ElementKind::Q1, 1, 1e-4) - reduced), 0.05 * reduced);
}

TEST(Friction, CoulombFrictionNeverLowersThePressure) {
  const double frictionless = pressure(fem::ElementKind::Q2, 2, 1e-3, 0.0);
  const double mild = pressure(fem::ElementKind::Q2, 2, 1e-3, 0.1);
  const double strong = pressure(fem::ElementKind::Q2, 2, 1e-3, 0.2);
  EXPECT_GT(mild, frictionless);
  EXPECT_GT(strong, mild);
}

} // namespace
} // namespace formflow
