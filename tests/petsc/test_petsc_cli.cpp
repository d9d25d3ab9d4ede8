// SPDX-License-Identifier: MIT
// The PETSc back-end from the command line: PETSc options pass through to its
// options database, the monitor shows the Krylov iterations, summary.json records
// the linear algebra, and a misspelt option is exit 2 with nothing written.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace formflow {
namespace {

using testing::has_text;
using testing::quoted;

constexpr const char* small_case = "--set mesh.size=2.5 --set solver.linear=petsc ";

TEST(PetscCli, CommandLineOptionsReachTheSolverAndTheMonitorShowsKrylovIterations) {
  testing::ScratchDirectory scratch("formflow-petsc-cli");
  // GMRES preconditioned by the exact MUMPS factorisation: one iteration per solve.
  const testing::CliResult run =
      testing::run_cli("run -o " + quoted((scratch / "results").string()) + " " + small_case +
                           "-ksp_type gmres -ksp_rtol 1e-12",
                       scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has_text(run.out, "krylov"));
  const auto summary =
      nlohmann::json::parse(testing::read_text(scratch / "results" / "summary.json"));
  const auto& algebra = summary.at("linear_algebra");
  EXPECT_EQ(algebra.at("solver"), "petsc-gmres-cholesky");
  EXPECT_EQ(algebra.at("ranks"), 1);
  const auto& per_step = algebra.at("iterations_per_step");
  ASSERT_EQ(per_step.size(), summary.at("history").size());
  long total = 0;
  for (const auto& count : per_step) {
    EXPECT_GE(count.get<long>(), 1);
    total += count.get<long>();
  }
  EXPECT_LE(total, algebra.at("iterations").get<long>()); // plus the start's solve
}

TEST(PetscCli, AMisspeltCommandLineOptionIsExitTwoAndWritesNothing) {
  testing::ScratchDirectory scratch("formflow-petsc-cli");
  const testing::CliResult run = testing::run_cli(
      "run -q -o " + quoted((scratch / "results").string()) + " " + small_case + "-ksp_tyep cg",
      scratch.path());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(has_text(run.err, "command line: -ksp_tyep: -ksp_tyep was read by no PETSc object"));
  EXPECT_FALSE(std::filesystem::exists(scratch / "results" / "summary.json"));
}

TEST(PetscCli, AMisspeltCaseOptionNamesTheKeyAndItsLine) {
  testing::ScratchDirectory scratch("formflow-petsc-cli");
  const std::filesystem::path case_file = scratch / "case.toml";
  {
    std::ofstream out(case_file);
    out << "[mesh]\nsize = 2.5\n[solver]\nlinear = \"petsc\"\npetsc_options = \"-pc_tyep lu\"\n";
  }
  const testing::CliResult run = testing::run_cli(
      "run -q -o " + quoted((scratch / "results").string()) + " " + quoted(case_file.string()),
      scratch.path());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(has_text(run.err, "case.toml:5: solver.petsc_options"));
  EXPECT_TRUE(has_text(run.err, "-pc_tyep"));
  EXPECT_FALSE(std::filesystem::exists(scratch / "results" / "summary.json"));
}

} // namespace
} // namespace formflow
