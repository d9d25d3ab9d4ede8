// SPDX-License-Identifier: MIT
// Issue 15, "Round = axisymmetric": a round billet through a conical die modelled in
// 3D (the O-grid quarter model, two symmetry planes) agrees with the axisymmetric
// run of the same case on the comparable mesh (as many cells along the radius as
// the meridian has rows), within the two models' discretisation errors and within
// the 1 %. The ladder to h = 1/8 is tests/long/test_round_axisymmetric_ladder.cpp.
#include "formflow/app/simulation.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

namespace formflow::testing {
namespace {

/// cases/conical-die-rod-extrusion.toml (30° cone, 50 % area reduction, μ = 0.05 on
/// the die, sticking ram, nodal normals) at `size`, axisymmetric or the 3D quarter.
post::Results conical_die(Real size, bool solid) {
  std::vector<io::Override> edits = {{"mesh.size", fmt::format("{}", size)},
                                     {"solver.tolerance", "1e-8"}};
  if (solid)
    for (const io::Override& edit : std::vector<io::Override>{{"geometry.symmetry", "plane"},
                                                              {"geometry.dimension", "3"},
                                                              {"geometry.section", "round"}})
      edits.push_back(edit);
  const post::Results results =
      app::simulate(
          io::load_case(std::string(FORMFLOW_SOURCE_DIR) + "/cases/conical-die-rod-extrusion.toml",
                        edits))
          .results;
  EXPECT_TRUE(results.converged()) << solvers::stop_reason_name(results.stop_reason);
  return results;
}

TEST(RoundIsAxisymmetric, QuarterModelAgreesWithTheAxisymmetricRunWithinTheDiscretisationError) {
  const Real coarse = 0.5, fine = 0.25;
  const Real axisymmetric_coarse = conical_die(coarse, false).pressure.ram_reaction;
  const Real solid_coarse = conical_die(coarse, true).pressure.ram_reaction;
  const Real axisymmetric = conical_die(fine, false).pressure.ram_reaction;
  const Real solid = conical_die(fine, true).pressure.ram_reaction;

  // Both discretise the same continuum problem. Each converges at least at first
  // order here (the die-corner and ram-corner singularities; the ladder of
  // docs/validation.md halves the change per halving of h), so its error at h is at
  // most its change from 2h to h: e(h) ≈ Δ/(2^r − 1) ≤ Δ for r ≥ 1. The two runs
  // at h differ by at most the sum of their errors.
  const Real axisymmetric_change = axisymmetric_coarse - axisymmetric;
  const Real solid_change = solid_coarse - solid;
  EXPECT_LT(std::abs(solid - axisymmetric), std::abs(axisymmetric_change) + std::abs(solid_change))
      << solid << " vs " << axisymmetric;
  // The number, on the comparable mesh.
  EXPECT_LT(std::abs(solid - axisymmetric), 0.01 * axisymmetric) << solid << " vs " << axisymmetric;
  // Both fall under refinement (the coarse meshes overestimate the load).
  EXPECT_GT(axisymmetric_change, 0.0);
  EXPECT_GT(solid_change, 0.0);
}

} // namespace
} // namespace formflow::testing
