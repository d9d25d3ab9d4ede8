// SPDX-License-Identifier: MIT
// The coupled manufactured solution of hot forming (issue 18): the smooth velocity and
// T = T₀ + ΔT sin(πx/2)(1 + ½cos πy) with the Sellars–Tegart law at the point's T, the
// heat source β σ_p ε̄̇ of the discrete flow and convection by the discrete velocity,
// solved by the staggered loop of a hot run; observed orders on the finest pair.
#include "verification/thermal_manufactured_support.hpp"

namespace formflow {
namespace {

using testing::errors_of;
using testing::expect_orders;

// Fast: one pair each (observed: Q1 1.00, 1.96, 1.00, 1.99 on 8 → 16; Q2 1.98, 2.94, 2.00,
// 3.00 on 4 → 8). The three-rung ladders are in tests/long/test_thermal_manufactured_long.cpp.
TEST(ThermalManufactured, Q1OrdersAreOneAndTwo) {
  expect_orders(1, errors_of(fem::ElementKind::Q1, 1.0 / 8),
                errors_of(fem::ElementKind::Q1, 1.0 / 16));
}

TEST(ThermalManufactured, Q2OrdersAreTwoAndThree) {
  // Third order in L² for T needs the SUPG residual's −κΔT_h (Q2 second derivatives).
  expect_orders(2, errors_of(fem::ElementKind::Q2, 1.0 / 4),
                errors_of(fem::ElementKind::Q2, 1.0 / 8));
}

} // namespace
} // namespace formflow
