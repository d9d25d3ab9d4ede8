// SPDX-License-Identifier: MIT
// `formflow study` of a case with [adapt]: the uniform ladder, the adaptive run from its
// first rung, and the picture of the load error against dofs (issue 17).
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace formflow {
namespace {

namespace fs = std::filesystem;

/// The rows of adaptive.csv, split at commas (no quoting in that file).
std::vector<std::vector<std::string>> adaptive_rows_of_study(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream text(testing::read_text(file));
  std::string line;
  std::getline(text, line); // header
  while (std::getline(text, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(StudyAgainstAdaptive, DrawsLoadErrorAgainstDofsForUniformAndAdaptive) {
  // The sticking ram on the tiny ladder h = 5, 2.5 (Q2; about 1 s in all) and two
  // adaptive cycles from h = 5: what the picture needs, not the benchmark's accuracy.
  testing::ScratchDirectory scratch{"formflow-study-adaptive"};
  const fs::path out = scratch.path() / "out";
  const testing::CliResult result = testing::run_cli(
      "study --vary mesh.size=5,2.5 --set process.ram=sticking --set material.alpha=1e-4 "
      "--set penalty.d=1e-4 --set adapt.target_error=1e-3 --set adapt.max_cycles=2 "
      "--exact-load 2.5707963267948966 -q -o " +
          testing::quoted(out.string()),
      scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* file :
       {"study.csv", "adaptive.csv", "load_error_dofs.png", "load_error_dofs.svg", "report.html"})
    EXPECT_TRUE(fs::exists(out / file) && fs::file_size(out / file) > 0) << file;
  const auto rows = adaptive_rows_of_study(out / "adaptive.csv");
  // Two uniform rungs, each with an estimate (solver.load_error "none" is taken as
  // "refined" on the rungs of such a study), then the adaptive cycles.
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(rows[k][0], "uniform");
    EXPECT_FALSE(rows[k][4].empty()) << "rung " << k << " has no estimate";
  }
  EXPECT_EQ(rows[2][0], "adaptive");
  EXPECT_EQ(rows[3][0], "adaptive");
  // The adaptive run starts from the first rung's case: cycle 0 is that very run, the
  // same mesh and the same deterministic solve, so the same dofs and load (to the
  // digits written, {:.10g}).
  EXPECT_EQ(rows[2][2], rows[0][2]);
  EXPECT_EQ(rows[2][3], rows[0][3]);
  // Then it refines where the indicators are: more dofs, a lower load (kinematic
  // approximations from above) and a smaller estimate.
  EXPECT_GT(std::stol(rows[3][2]), std::stol(rows[2][2]));
  EXPECT_LT(std::stod(rows[3][3]), std::stod(rows[2][3]));
  EXPECT_LT(std::stod(rows[3][4]), std::stod(rows[2][4]));
  // report.html carries the study picture and the load-error picture.
  const std::string report = testing::read_text(out / "report.html");
  const std::string picture = "src=\"data:image/svg+xml;base64,";
  const auto first = report.find(picture);
  ASSERT_NE(first, std::string::npos);
  EXPECT_NE(report.find(picture, first + 1), std::string::npos);
}

} // namespace
} // namespace formflow
