// SPDX-License-Identifier: MIT
// The residual's power in exact friction's Newton stop rule (solvers/power_residual.hpp):
// |Σ_free u_i f_i| / |Σ_driven u_i f_i| on a chain of four dofs, dof 0 driven, dof 3 held.
#include "formflow/solvers/power_residual.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace formflow::solvers {
namespace {

// Dofs 0 (driven) and 3 (held at zero) are prescribed; 1 and 2 are free.
assembly::ScatterPlan chain_plan() {
  std::vector<bool> prescribed{true, false, false, true};
  assembly::BlockDofs blocks;
  for (Index e = 0; e < 3; ++e) blocks.add({e, e + 1});
  return assembly::ScatterPlan(4, prescribed, blocks);
}

TEST(PowerResidual, IsTheFreeRowsPowerOverTheDrivenPower) {
  const assembly::ScatterPlan plan = chain_plan();
  VectorX velocity(4), force(4);
  velocity << 2.0, 1.5, 0.5, 0.0;
  force << 3.0, 0.2, -0.4, 7.0; // the held dof's reaction does no power
  EXPECT_DOUBLE_EQ(power_residual(plan, {0}, velocity, force), (0.3 - 0.2) / 6.0);
}

TEST(PowerResidual, IsZeroInBalanceAndFreeOfUnits) {
  const assembly::ScatterPlan plan = chain_plan();
  VectorX velocity(4), force(4);
  velocity << 2.0, 1.5, 0.5, 0.0;
  force << 3.0, 0.0, 0.0, -1.0;
  EXPECT_EQ(power_residual(plan, {0}, velocity, force), 0.0);
  force << 3.0, 0.2, -0.4, 7.0;
  const Real reference = power_residual(plan, {0}, velocity, force);
  EXPECT_DOUBLE_EQ(power_residual(plan, {0}, VectorX(1e-3 * velocity), VectorX(1e6 * force)),
                   reference);
}

TEST(PowerResidual, WithoutDrivenPowerNothingIsBalanced) {
  const assembly::ScatterPlan plan = chain_plan();
  VectorX velocity(4), force(4);
  velocity << 0.0, 1.5, 0.5, 0.0;
  force << 3.0, 0.2, -0.4, 7.0;
  EXPECT_EQ(power_residual(plan, {0}, velocity, force), std::numeric_limits<Real>::infinity());
}

} // namespace
} // namespace formflow::solvers
