// SPDX-License-Identifier: MIT
// The sticking-ram benchmark on structured and Gmsh meshes as h halves (minutes: label long).
#include "formflow/app/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace formflow {
namespace {

double sticking_ram_pressure(mesh::MeshSource source, double size) {
  io::Case case_;
  case_.process.ram = physics::RamCondition::Sticking;
  case_.mesh.source = source;
  case_.mesh.size = size;
  const post::Results results = app::simulate(case_).results;
  EXPECT_TRUE(results.converged()) << "h = " << size;
  return results.pressure.ram_reaction;
}

TEST(GmshLadder, StickingRamOnBothMeshesApproachesTheSlipLinePressure) {
#if !FORMFLOW_WITH_GMSH
  GTEST_SKIP() << "built without Gmsh";
#endif
  // Both meshes converge to Hill's (1 + π/2) k = 2.5708 at first order; at each
  // h they differ by less than the structured error, and the Gmsh error falls
  // as h halves. Numbers: docs/gmsh-meshes.md.
  const double slip_line = 1.0 + std::numbers::pi / 2.0;
  double previous_gmsh_error = 0.0;
  for (const double size : {1.0, 0.5, 0.25}) {
    const double p_structured = sticking_ram_pressure(mesh::MeshSource::Structured, size);
    const double p_gmsh = sticking_ram_pressure(mesh::MeshSource::Gmsh, size);
    std::printf("h = %g: structured %.4f, Gmsh %.4f\n", size, p_structured, p_gmsh);
    EXPECT_LT(std::abs(p_gmsh - p_structured), p_structured - slip_line) << "h = " << size;
    const double gmsh_error = p_gmsh - slip_line;
    EXPECT_GT(gmsh_error, 0.0) << "h = " << size;
    if (previous_gmsh_error > 0) {
      EXPECT_LT(gmsh_error, previous_gmsh_error) << "h = " << size;
    }
    previous_gmsh_error = gmsh_error;
  }
}

} // namespace
} // namespace formflow
