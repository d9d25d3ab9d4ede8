// SPDX-License-Identifier: MIT
// Issue 15: a rectangular bar through a square die (quarter model) at fixed half
// heights 1 → 0.5 and growing half widths W → W − 0.5 (the die steps in by the same
// 0.5 on both faces): the area reduction tends to the plane one, and the ram
// pressure falls toward the plane-strain value of the same (x, y) mesh. The table of
// docs/3d.md is this test's output.
#include "formflow/app/simulation.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

namespace formflow::testing {
namespace {

/// {L_c = 1, H_in = 1, H_out = 0.5, L_e = 1} at h = 0.25, Q2 2×2×2, μ = 0; in 3D the
/// rectangle with half widths `width` → `width` − 0.5, in 2D the plane channel.
post::Results square_die(Real width, bool solid) {
  std::vector<io::Override> edits = {{"geometry.container_length", "1"},
                                     {"geometry.entry_half_height", "1"},
                                     {"geometry.exit_half_height", "0.5"},
                                     {"geometry.exit_length", "1"},
                                     {"mesh.size", "0.25"},
                                     {"friction.mu", "0"},
                                     {"solver.tolerance", "1e-8"}};
  if (solid)
    for (const io::Override& edit :
         std::vector<io::Override>{{"geometry.dimension", "3"},
                                   {"geometry.section", "rectangle"},
                                   {"geometry.entry_half_width", fmt::format("{}", width)},
                                   {"geometry.exit_half_width", fmt::format("{}", width - 0.5)}})
      edits.push_back(edit);
  const post::Results results = app::simulate(io::load_case("", edits)).results;
  EXPECT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  return results;
}

TEST(RectangleWidthLadder, RamPressureFallsTowardThePlaneStrainValueAsTheBarWidens) {
  const Real plane_strain = square_die(0, false).pressure.ram_reaction;
  fmt::print("plane strain (2D, same (x, y) mesh): {:.6f}\n", plane_strain);
  fmt::print("| W_in → W_out | area reduction | dofs | Newton iterations | ram pressure | "
             "excess over plane strain |\n|---|---|---|---|---|---|\n");
  std::vector<Real> excess;
  Real previous = 0.0;
  for (Real width : {1.0, 2.0, 4.0, 8.0}) {
    const post::Results bar = square_die(width, true);
    const Real pressure = bar.pressure.ram_reaction;
    excess.push_back(pressure - plane_strain);
    fmt::print("| {} → {} | {:.3f} | {} | {} | {:.6f} | {:.6f} |\n", width, width - 0.5,
               width / (0.5 * (width - 0.5)), bar.n_dofs, bar.iterations, pressure, excess.back());
    // The reaction is the total power (the power balance of the rectangle).
    EXPECT_NEAR(pressure, bar.pressure.total_power, 1e-7 * pressure);
    if (width > 1.0) {
      EXPECT_LT(pressure, previous) << "width " << width;
    }
    previous = pressure;
  }
  // The excess is the z step's extra work and the side faces' effect, both a share
  // ≈ 0.5/W of the section: it shrinks toward zero, by more than 4 over W = 1 → 8.
  for (Real gap : excess) EXPECT_GT(gap, 0.0);
  EXPECT_LT(excess.back(), excess.front() / 4);
}

} // namespace
} // namespace formflow::testing
