// SPDX-License-Identifier: MIT
// A die channel from CAD (mesh.source = "cad") from the command line: the STEP solid of
// cases/cad-conical-die.toml is meshed and solved; a file that is not STEP or BREP is
// refused before OpenCASCADE sees it, and a surface map that misses or invents a
// surface is refused by key, with nothing written.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using testing::has_text;
using testing::quoted;

const std::string cad_case = FORMFLOW_SOURCE_DIR "/cases/cad-conical-die.toml";

TEST(CadDieCli, TheStepSolidIsMeshedAndSolved) {
  testing::ScratchDirectory scratch("formflow-cad-cli");
  const fs::path out = scratch / "out";
  const testing::CliResult result = testing::run_cli("run -q -o " + quoted(out.string()) + " " +
                                                         quoted(cad_case) + " --set mesh.size=0.5",
                                                     scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = nlohmann::json::parse(testing::read_text(out / "summary.json"));
  ASSERT_TRUE(summary.at("converged").get<bool>());
  EXPECT_EQ(summary.at("mesh").at("source"), "cad");
  EXPECT_EQ(summary.at("case").at("mesh").at("cell"), "tetrahedron");
  EXPECT_EQ(summary.at("case").at("contact").at("normals"), "nodes"); // a curved die's default
  // The ram's work is the power dissipated in the field the loop stopped at: both read
  // the same velocity, apart by the residual's work, which the stop rule keeps below δ·p.
  const double p = summary.at("pressure").at("ram_reaction").get<double>();
  EXPECT_NEAR(summary.at("pressure").at("total_power").get<double>(), p, 1e-4 * p);
  EXPECT_TRUE(fs::exists(out / "exit_velocity.png"));
}

TEST(CadDieCli, WhatIsNoCadSolidOrNoMapIsRefusedByKey) {
  testing::ScratchDirectory scratch("formflow-cad-cli");
  {
    // A Gmsh script named like a STEP file: it must never reach a parser that would run it.
    std::ofstream(scratch / "script.step")
        << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0,0,0,1,1,1};\n";
    std::ofstream(scratch / "die.geo") << "ISO-10303-21;\n";
  }
  const std::vector<std::pair<std::string, std::string>> refusals = {
      {"mesh.cad_file=" + (scratch / "script.step").string(), "does not begin like a STEP"},
      {"mesh.cad_file=" + (scratch / "die.geo").string(), "not a STEP or BREP file"},
      {"mesh.cad_file=" + (scratch / "missing.step").string(), "not a readable regular file"},
      {"mesh.boundaries={\"3\" = \"rear\"}", "have no part"},
      {"mesh.boundaries.9=die", "mesh.boundaries.9"},
      {"mesh.cell=hexahedron", "mesh.cell"},
      {"geometry.dimension=2", "geometry.dimension"},
  };
  for (const auto& [setting, words] : refusals) {
    SCOPED_TRACE(setting);
    const fs::path out = scratch / "out";
    const testing::CliResult result = testing::run_cli(
        "run -q -o " + quoted(out.string()) + " " + quoted(cad_case) + " --set " + quoted(setting),
        scratch.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_TRUE(has_text(result.err, words));
    EXPECT_FALSE(fs::exists(out));
  }
}

} // namespace
} // namespace formflow
