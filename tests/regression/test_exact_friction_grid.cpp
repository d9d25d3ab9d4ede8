// SPDX-License-Identifier: MIT
// Exact Coulomb friction by Newton, its default path (the semismooth Newton on nodal
// contact points, the regularised referee on nodal points too), over a subset of issue
// 16's grid (the full grid,
// with h = 0.25, μ up to 0.5 and δ = 1e-8, is tests/long/test_exact_friction_grid.cpp):
// every case converges to δ = 1e-4 within 25 iterations, coarse levels included, its
// Coulomb residual below δ, and its load agrees with the regularised law's at
// d_T = 1e-6 within the bound derived in support/exact_friction_grid.hpp.
// Measured iteration counts: docs/friction.md "Session 8" and "Session 9".
#include "support/exact_friction_grid.hpp"

#include <gtest/gtest.h>

#include <tuple>

namespace formflow::testing {
namespace {

using physics::RamCondition;

class ExactFrictionGrid
    : public ::testing::TestWithParam<std::tuple<RamCondition, double, double>> {};

TEST_P(ExactFrictionGrid, ConvergesInBoundedIterationsToTheRegularisedLimit) {
  const auto [ram, size, mu] = GetParam();
  FrictionGridCase c;
  c.exact_stick = true; // the exact law's default path
  c.ram = ram;
  c.size = size;
  c.mu = mu;
  check_grid_case(c, 1e-4, true);
}

// Q2 with the 2×2 rule, plane: mesh II (h = 1) and its refinement, both ram conditions,
// μ from the paper's 0.1 to 0.3 (the failing case is sticking, h = 0.5, μ = 0.2).
INSTANTIATE_TEST_SUITE_P(
    Q2Plane, ExactFrictionGrid,
    ::testing::Combine(::testing::Values(RamCondition::Sliding, RamCondition::Sticking),
                       ::testing::Values(1.0, 0.5), ::testing::Values(0.1, 0.2, 0.3)));

TEST(ExactFrictionGridOthers, AxisymmetricQ2) {
  FrictionGridCase c;
  c.exact_stick = true; // the exact law's default path
  c.size = 0.5;
  c.mu = 0.3;
  c.symmetry = physics::Symmetry::Axisymmetric;
  check_grid_case(c, 1e-4, true);
}

// The container sticks up to the ram (stick length 6.8 of 10): its stuck points load the
// ram's prescribed dofs, and the reaction used to differ from the total power by 1e-4
// relative at "convergence" (5.35224 against 5.35466 at δ = 1e-8), the free rows out of
// balance while the velocity had settled (docs/friction.md "Reaction and total power").
TEST(ExactFrictionGridOthers, AxisymmetricStickZoneUpToTheRam) {
  FrictionGridCase c;
  c.exact_stick = true; // the exact law's default path
  c.size = 1.0;
  c.mu = 0.5;
  c.symmetry = physics::Symmetry::Axisymmetric;
  check_grid_case(c, 1e-4, true);
}

/// A plane Q1 case with the one-point rule and the sticking ram on the exact law's default
/// path (friction.stick = "exact").
FrictionGridCase q1_one_point_sticking(Real size, Real mu) {
  FrictionGridCase c;
  c.exact_stick = true;
  c.ram = RamCondition::Sticking;
  c.size = size;
  c.mu = mu;
  c.element = fem::ElementKind::Q1;
  c.volumetric_points = 1;
  return c;
}

TEST(ExactFrictionGridOthers, Q1WithTheOnePointRule) {
  check_grid_case(q1_one_point_sticking(0.5, 0.2), 1e-4, true);
}

// Case 228 of the long test's grid (plane Q1 1×1, sticking ram, h = 0.25, μ = 0.3). Session
// 9's loop stopped "converged" at δ = 1e-8 with one container node (x = 2.25) held while
// its reaction asked for more than τ_f: the update clipped λ̂ onto the Coulomb disk, the
// node was held again, and its tangential row stayed out of balance, unseen by every stop
// test. Its load 3.0039179 lay 7.7e-6 from the regularised law's on the same points, over
// the derived bound (7.3e-6). That excess now counts in the Coulomb residual and such a
// node is released once the iterate has settled (docs/friction.md "Session 11"): the
// residual must be below δ and the load within the bound of
// support/exact_friction_grid.hpp. Which path the loop takes depends on the build: in
// session 11 main's binary no longer reached the false stop on this case, so this guards
// the case, while the held residual itself is tested in test_friction_residual.cpp.
TEST(ExactFrictionGridOthers, HeldNodeWhoseReactionLeavesTheCoulombDiskIsReleased) {
  const FrictionGridCase c = q1_one_point_sticking(0.25, 0.3);
  constexpr double tolerance = 1e-8;
  SCOPED_TRACE(grid_case_name(c));
  const post::Results exact = app::simulate(grid_case(c, true, tolerance)).results;
  ASSERT_TRUE(exact.converged()) << solvers::stop_reason_name(exact.stop_reason);
  EXPECT_LT(exact.augmentation.friction_residual, tolerance);
  EXPECT_LT(exact.augmentation.power_residual, tolerance);
  const post::Results regularised = app::simulate(grid_case(c, false, tolerance)).results;
  ASSERT_TRUE(regularised.converged());
  EXPECT_NEAR(regularised.pressure.ram_reaction, exact.pressure.ram_reaction,
              regularisation_bound(c, exact, tolerance));
}

} // namespace
} // namespace formflow::testing
