// SPDX-License-Identifier: MIT
// mesh.cell = "tetrahedron" from the command line on one layer of the slab (h = 1): every
// formulation that runs on P2+ tetrahedra converges (regularised and exact friction,
// Tresca, thermal, PETSc), PETSc gives CHOLMOD's load, and what does not run is refused
// by key with nothing written.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using testing::quoted;

constexpr const char* tetrahedral_slab =
    "--set geometry.dimension=3 --set geometry.section=slab --set geometry.thickness=1 "
    "--set mesh.size=1 --set mesh.cell=tetrahedron --set solver.load_error=none ";

struct TetrahedralRun {
  int exit_code = -1;
  std::string err;
  nlohmann::json summary;
};

TetrahedralRun run_tetrahedra(const testing::ScratchDirectory& scratch, const std::string& name,
                              const std::string& settings) {
  const fs::path out = scratch / name;
  const testing::CliResult result = testing::run_cli(
      std::string("run -q -o ") + quoted(out.string()) + " " + tetrahedral_slab + settings,
      scratch.path());
  TetrahedralRun run{result.exit_code, result.err, {}};
  if (fs::exists(out / "summary.json"))
    run.summary = nlohmann::json::parse(testing::read_text(out / "summary.json"));
  return run;
}

TEST(TetrahedraCli, EveryFormulationThatRunsConverges) {
  testing::ScratchDirectory scratch("formflow-tet-cli");
  for (const auto& [name, settings] :
       {std::pair<std::string, std::string>{"default", ""},
        {"regularised", "--set friction.mu=0.1"},
        {"exact", "--set friction.mu=0.1 --set friction.regularization=none"},
        {"tresca", "--set friction.m=0.3 --set friction.law=tresca"},
        {"nodal-normals", "--set friction.mu=0.1 --set contact.normals=nodes"},
        {"thermal", "--set thermal.enabled=true"}}) {
    SCOPED_TRACE(name);
    const TetrahedralRun run = run_tetrahedra(scratch, name, settings);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(run.summary.at("converged").get<bool>());
    EXPECT_EQ(run.summary.at("mesh").at("element"), "P2");
    EXPECT_GT(run.summary.at("pressure").at("ram_reaction").get<double>(), 0.0);
  }
}

TEST(TetrahedraCli, PetscGivesCholmodsLoad) {
  // The same Newton iteration with another linear solver: both stop once the relative
  // change is below δ = 1e-4, each within δ·p of the discrete solution, so within 2δ·p.
  testing::ScratchDirectory scratch("formflow-tet-cli");
  const TetrahedralRun cholmod = run_tetrahedra(scratch, "cholmod", "");
  const TetrahedralRun petsc = run_tetrahedra(scratch, "petsc", "--set solver.linear=petsc");
  ASSERT_EQ(cholmod.exit_code, 0) << cholmod.err;
  ASSERT_EQ(petsc.exit_code, 0) << petsc.err;
  const double p = cholmod.summary.at("pressure").at("ram_reaction").get<double>();
  EXPECT_NEAR(petsc.summary.at("pressure").at("ram_reaction").get<double>(), p, 2e-4 * p);
}

TEST(TetrahedraCli, WhatDoesNotRunIsRefusedByKey) {
  testing::ScratchDirectory scratch("formflow-tet-cli");
  const TetrahedralRun mini = run_tetrahedra(
      scratch, "mini-exact",
      "--set mesh.element=P1b --set friction.mu=0.1 --set friction.regularization=none");
  EXPECT_EQ(mini.exit_code, 2);
  EXPECT_NE(mini.err.find("friction.regularization"), std::string::npos) << mini.err;
  EXPECT_FALSE(fs::exists(scratch / "mini-exact"));
  const TetrahedralRun penalty =
      run_tetrahedra(scratch, "penalty", "--set formulation.type=penalty");
  EXPECT_EQ(penalty.exit_code, 2);
  EXPECT_NE(penalty.err.find("formulation.type"), std::string::npos) << penalty.err;
  EXPECT_FALSE(fs::exists(scratch / "penalty"));
}

} // namespace
} // namespace formflow
