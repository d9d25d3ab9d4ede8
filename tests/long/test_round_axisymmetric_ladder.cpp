// SPDX-License-Identifier: MIT
// Issue 15, "Round = axisymmetric", the ladder of docs/validation.md: the 3D quarter
// model of cases/conical-die-rod-extrusion.toml and its axisymmetric run at h = 1/2,
// 1/4, 1/8 (the 3D model at 1/8 is the 49 k-dof speed case of docs/3d.md): they
// agree within 1 % on every rung and converge together.
#include "formflow/app/simulation.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

namespace formflow::testing {
namespace {

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

TEST(RoundIsAxisymmetricLadder, AgreementWithinOnePercentOnEveryRungAndTheSameConvergence) {
  std::vector<Real> axisymmetric, solid;
  fmt::print("| h | axisymmetric dofs | p (axisymmetric) | 3D quarter dofs | p (3D quarter) | "
             "relative difference |\n|---|---|---|---|---|---|\n");
  for (Real size : {0.5, 0.25, 0.125}) {
    const post::Results plane = conical_die(size, false), quarter = conical_die(size, true);
    axisymmetric.push_back(plane.pressure.ram_reaction);
    solid.push_back(quarter.pressure.ram_reaction);
    const Real difference = std::abs(solid.back() - axisymmetric.back()) / axisymmetric.back();
    fmt::print("| {} | {} | {:.6f} | {} | {:.6f} | {:.2e} |\n", size, plane.n_dofs,
               axisymmetric.back(), quarter.n_dofs, solid.back(), difference);
    EXPECT_LT(difference, 0.01);
  }
  // Converging together: each halving of h changes both by amounts that agree to
  // the rungs' own differences, and the changes shrink (first order at least).
  for (std::size_t k = 1; k < solid.size(); ++k) {
    const Real plane_change = axisymmetric[k - 1] - axisymmetric[k];
    const Real solid_change = solid[k - 1] - solid[k];
    EXPECT_GT(plane_change, 0.0);
    EXPECT_GT(solid_change, 0.0);
    if (k > 1) {
      EXPECT_LT(plane_change, axisymmetric[k - 2] - axisymmetric[k - 1]);
      EXPECT_LT(solid_change, solid[k - 2] - solid[k - 1]);
    }
  }
}

} // namespace
} // namespace formflow::testing
