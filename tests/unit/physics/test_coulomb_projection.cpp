// SPDX-License-Identifier: MIT
// The projection factor of the exact Coulomb law and the regularised stick criterion.
#include "formflow/physics/friction.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

namespace formflow::testing {
namespace {

TEST(CoulombProjection, IsIdentityInsideTheDiscAndRadialOutside) {
  // Inside (and on) the disc |t| ≤ τ_f the trial traction is kept: stick.
  EXPECT_EQ(physics::coulomb_projection_factor(0.5, 0.2), 1.0);
  EXPECT_EQ(physics::coulomb_projection_factor(0.5, 0.5), 1.0);
  // Outside it is scaled back to the circle: |s t| = τ_f, slip.
  EXPECT_TRUE(approx(physics::coulomb_projection_factor(0.5, 2.0) * 2.0, 0.5, 1e-15));
  // No threshold (friction off or tensile σ̄_N): no traction at all, even for t = 0.
  EXPECT_EQ(physics::coulomb_projection_factor(0.0, 0.0), 0.0);
  EXPECT_EQ(physics::coulomb_projection_factor(0.0, 3.0), 0.0);
}

TEST(RegularizedStick, MeansSlipBelowSevenDT) {
  // |σ_T| < 0.99 τ_f ⇔ |u_T| < 0.99/√(1 − 0.99²) d_T = 7.018 d_T.
  const double d_t = 1e-6, tau = 0.3;
  EXPECT_TRUE(physics::is_sticking_regularized(tau, 7.0 * d_t, d_t));
  EXPECT_FALSE(physics::is_sticking_regularized(tau, 7.05 * d_t, d_t));
  EXPECT_FALSE(physics::is_sticking_regularized(0.0, 0.0, d_t)); // no friction: never stick
}

} // namespace
} // namespace formflow::testing
