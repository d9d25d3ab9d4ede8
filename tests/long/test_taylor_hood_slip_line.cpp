// SPDX-License-Identifier: MIT
// Taylor–Hood (Q2–Q1) on issue 5's acceptance run: sticking ram, exact
// incompressibility (d = 0), h = 0.25 and 0.125 (docs/mixed.md, Taylor–Hood
// table): within 2 % of the slip-line (1 + π/2) k = 2.5708 and no checkerboard
// in the container. About 15 min on a loaded two-core machine.
#include "formflow/app/simulation.hpp"
#include "support/approx.hpp"
#include "verification/checkerboard.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace formflow {
namespace {

constexpr double slip_line = 1.0 + std::numbers::pi / 2.0;

/// Solves at `size`, prints the load measures, checks convergence, smoothness
/// and reaction = total power; returns the ram pressure.
double solve_taylor_hood(Real size) {
  io::Case case_;
  case_.process.ram = physics::RamCondition::Sticking;
  case_.mesh.size = size;
  case_.formulation.type = assembly::FormulationType::Mixed;
  case_.formulation.pressure = fem::PressureSpace::Q1;
  case_.penalty.d = 0.0;
  const app::Simulation simulation = app::simulate(case_);
  const post::Results& results = simulation.results;
  const double share = testing::checkerboard_share(simulation.plane_mesh(), size,
                                                   results.fields.cell_hydrostatic_stress, 10.0);
  std::printf("Taylor-Hood h = %g: ram reaction %.4f, power balance %.4f, total power %.4f, "
              "mean -σ_H near ram %.4f, iterations %d, checkerboard share %.2e, %.0f s\n",
              size, results.pressure.ram_reaction, results.pressure.power_balance,
              results.pressure.total_power, results.pressure.mean_hydrostatic_near_ram,
              results.iterations, share, results.timing.get("total"));
  std::fflush(stdout);
  EXPECT_TRUE(results.converged());
  EXPECT_LT(share, 0.01);
  EXPECT_TRUE(testing::approx(results.pressure.ram_reaction, results.pressure.total_power, 1e-4));
  return results.pressure.ram_reaction;
}

TEST(TaylorHoodSlipLine, ExactIncompressibilityWithinTwoPercentAtH0125) {
  const double coarse = solve_taylor_hood(0.25);
  const double fine = solve_taylor_hood(0.125);
  // The acceptance bound (2 %), not a fit; first-order decrease with h.
  EXPECT_TRUE(testing::approx(fine, slip_line, 0.02));
  EXPECT_LT(std::abs(fine - slip_line), 0.75 * std::abs(coarse - slip_line));
}

} // namespace
} // namespace formflow
