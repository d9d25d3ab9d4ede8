// SPDX-License-Identifier: MIT
// The Coulomb residual of the exact-friction stop rule (solvers/friction_residual.hpp):
// zero exactly on the Coulomb law, the slip left at a stuck point relative to the
// slip on Γ3, the misalignment at a slip point, and no dependence on the algorithm's
// augmentation or on the units of tractions and velocities.
#include "formflow/solvers/friction_residual.hpp"

#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace formflow::solvers {
namespace {

using Points = std::vector<assembly::ContactPoint<2>>;

/// A Γ3 point on a wall with normal +y: u_T = (slip, 0), λ_T = (traction, 0).
assembly::ContactPoint<2> wall_point(Real threshold, Real slip, Real traction, Real weight = 1) {
  assembly::ContactPoint<2> point;
  point.normal = Point<2>(0, 1);
  point.weight = weight;
  point.friction_threshold = threshold;
  point.tangential_velocity = Point<2>(slip, 0);
  point.friction_traction = Point<2>(traction, 0);
  return point;
}

/// A sliding point (λ = τ_f û_T) and a stuck one (u_T = 0, |λ| < τ_f): the exact law.
Points coulomb_solution() {
  return {wall_point(0.5, 1.0, 0.5), wall_point(0.5, 0.0, -0.3, 2.0), wall_point(0.2, 0.4, 0.2)};
}

TEST(FrictionResidual, IsZeroOnTheCoulombLaw) {
  EXPECT_EQ(friction_residual(coulomb_solution()), 0.0);
}

TEST(FrictionResidual, IsZeroWithoutFriction) {
  EXPECT_EQ(friction_residual(Points{}), 0.0);
  EXPECT_EQ(friction_residual(Points{wall_point(0.0, 1.0, 0.0)}), 0.0); // τ_f = 0: off
  EXPECT_EQ(friction_residual(Points{wall_point(0.5, 1.0, 0.0)}), 0.0); // not loaded yet
}

TEST(FrictionResidual, MeasuresTheSlipLeftAtAStuckPointRelativeToTheSlipOnGamma3) {
  // One stuck point creeping at ε: at the scale r̄ = ‖λ‖/‖u_T‖ its trial traction
  // stays inside the disc, so its residual is r̄ ε, i.e. ε/‖u_T‖ relative to ‖λ‖.
  constexpr Real creep = 1e-6;
  Points points = coulomb_solution();
  points[1].tangential_velocity = Point<2>(creep, 0);
  Real traction = 0, slip = 0;
  for (const auto& point : points) {
    traction += point.friction_traction.squaredNorm() * point.weight;
    slip += point.tangential_velocity.squaredNorm() * point.weight;
  }
  const Real expected = creep * std::sqrt(points[1].weight / slip);
  // Rounding: the residual is λ − (λ + r̄ ε), a cancellation with relative error
  // ε_mach |λ|/(r̄ ε) ≈ 2e-16 · 0.3/6e-7 ≈ 1e-10.
  EXPECT_TRUE(testing::approx(friction_residual(points), expected, 1e-9));
}

TEST(FrictionResidual, MeasuresASlipAgainstItsTraction) {
  // The first point slides forward but its traction pulls it forward too: the
  // projection of λ + r̄ u_T flips λ, an error of the traction's own size.
  Points points = coulomb_solution();
  points[0].friction_traction = Point<2>(-0.5, 0);
  EXPECT_GT(friction_residual(points), 0.5);
}

TEST(FrictionResidual, DoesNotDependOnUnitsOfTractionOrVelocity) {
  Points points = coulomb_solution();
  points[1].tangential_velocity = Point<2>(1e-3, 0);
  points[2].friction_traction = Point<2>(0.15, 0.0); // below τ_f while sliding
  const Real reference = friction_residual(points);
  ASSERT_GT(reference, 0.0);
  for (auto& point : points) {
    point.tangential_velocity *= 7.0;
    point.friction_traction *= 1e3;
    point.friction_threshold *= 1e3;
  }
  // Every term scales by the same factor; only rounding differs.
  EXPECT_TRUE(testing::approx(friction_residual(points), reference, 1e-12));
}

TEST(FrictionResidual, TestsOnlyTheDiscWhenNothingSlips) {
  Points points{wall_point(0.5, 0.0, 0.3), wall_point(0.5, 0.0, 0.7)}; // |λ| > τ_f at one
  // λ − proj(λ) = 0.2 at the second point: 0.2 / √(0.3² + 0.7²).
  EXPECT_TRUE(testing::approx(friction_residual(points), 0.2 / std::sqrt(0.58), 1e-12));
}

// A node the exact-stick step held (u_T = 0) whose reaction asks λ̂ = 0.6 over τ_f = 0.5:
// the update projects it to 0.5, which with u_T = 0 satisfies Coulomb exactly, so the
// projected residual is blind to the row's imbalance W (0.6 − 0.5) (issue 16, case 228).
TEST(HeldFrictionResidual, SeesAHeldReactionBeyondTheCoulombLimit) {
  Points points = coulomb_solution();
  points[1].friction_traction = Point<2>(-0.5, 0); // projected onto the disc: on its edge
  std::vector<Point<2>> asked(points.size(), Point<2>::Zero());
  asked[1] = Point<2>(-0.6, 0.0);
  ASSERT_EQ(friction_residual(points), 0.0);
  // Judged with the asked 0.6 (the scale r̄ multiplies u_T = 0 there): 0.1 at weight 2,
  // relative to ‖λ‖ with λ = 0.6 at that point. Rounding only: the excess 0.6 − 0.5 loses
  // a factor 6 of relative accuracy to cancellation (6ε), and the sums of three squares,
  // the quotient and the square roots on both sides add about 10ε more: 32ε bounds it.
  const Real traction = 0.5 * 0.5 * 1.0 + 0.6 * 0.6 * 2.0 + 0.2 * 0.2 * 1.0;
  const Real expected = 0.1 * std::sqrt(2.0 / traction);
  constexpr Real rounding = 32 * std::numeric_limits<Real>::epsilon();
  EXPECT_TRUE(testing::approx(held_friction_residual(points, asked, {1}), expected, rounding));
}

TEST(HeldFrictionResidual, IsTheProjectedResidualWhereTheReactionLiesInsideTheDisc) {
  Points points = coulomb_solution();
  std::vector<Point<2>> asked(points.size(), Point<2>::Zero());
  asked[1] = points[1].friction_traction + Point<2>(0.0, 0.25); // a normal part: dropped
  EXPECT_EQ(held_friction_residual(points, asked, {1}), 0.0);
}

} // namespace
} // namespace formflow::solvers
