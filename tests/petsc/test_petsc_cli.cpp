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
#include <vector>

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

/// A case file whose solver.petsc_options is `options`, on the small mesh.
std::filesystem::path case_with_options(const testing::ScratchDirectory& scratch,
                                        const std::string& options) {
  const std::filesystem::path case_file = scratch / "case.toml";
  std::ofstream out(case_file);
  out << "[mesh]\nsize = 2.5\n[solver]\nlinear = \"petsc\"\npetsc_options = \"" << options
      << "\"\n";
  return case_file;
}

/// A case file is data: a viewer, an options file or -help in solver.petsc_options is
/// refused by `check` and by `run` (exit 2, the key, its line and what is allowed), and
/// the file the viewer names is never written.
TEST(PetscCli, ACaseFileCannotWriteOrReadFilesThroughPetscOptions) {
  testing::ScratchDirectory scratch("formflow-petsc-cli");
  const std::string leak = (scratch / "leak.txt").string();
  for (const std::string& options : std::vector<std::string>{
           "-ksp_view ascii:" + leak, "-mat_view ascii:" + leak, "-ksp_monitor " + leak,
           "-log_view ascii:" + leak, std::string("-ksp_type cg -options_file /etc/passwd"),
           std::string("-help"), "-malloc_dump " + leak, "-ksp_type ascii:" + leak}) {
    const std::filesystem::path case_file = case_with_options(scratch, options);
    for (const std::string& command : std::vector<std::string>{
             "check ", "run -q -o " + quoted((scratch / "results").string()) + " "}) {
      const testing::CliResult run =
          testing::run_cli(command + quoted(case_file.string()), scratch.path());
      EXPECT_EQ(run.exit_code, 2) << command << options << "\n" << run.err << run.out;
      EXPECT_TRUE(has_text(run.err, "case.toml:5: solver.petsc_options")) << run.err;
      EXPECT_TRUE(has_text(run.err, "a case may set solver types")) << run.err;
      EXPECT_FALSE(std::filesystem::exists(leak)) << command << options;
      EXPECT_FALSE(std::filesystem::exists(scratch / "results")) << command << options;
    }
  }
}

/// The command line is the user's own: PETSc's full options stay there, a viewer
/// included.
TEST(PetscCli, TheCommandLineKeepsPetscsViewers) {
  testing::ScratchDirectory scratch("formflow-petsc-cli");
  const std::filesystem::path view = scratch / "ksp.txt";
  const testing::CliResult run =
      testing::run_cli("run -q -o " + quoted((scratch / "results").string()) + " " + small_case +
                           "-ksp_view ascii:" + quoted(view.string()),
                       scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has_text(testing::read_text(view), "KSP Object"));
}

} // namespace
} // namespace formflow
