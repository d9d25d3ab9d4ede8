// SPDX-License-Identifier: MIT
// `formflow study`: files written on success, exit 2 with nothing written on bad input,
// exit 3 with marked files when a rung does not converge.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;

class StudyCommand : public ::testing::Test {
protected:
  /// Runs `formflow study ARGS -q -o OUT`; returns the exit code, stderr in `err_`.
  int study(const std::string& arguments) {
    const formflow::testing::CliResult result = formflow::testing::run_cli(
        "study " + arguments + " -q -o " + formflow::testing::quoted(output().string()),
        scratch_.path());
    err_ = result.err;
    return result.exit_code;
  }
  fs::path output() const { return scratch_ / "out"; }
  std::string csv() const { return formflow::testing::read_text(output() / "study.csv"); }

  formflow::testing::ScratchDirectory scratch_{"formflow-study"};
  std::string err_;
};

const std::string manufactured = "--set verification.solution=smooth --set mesh.element=Q1 "
                                 "--set integration.volumetric=1 --set material.alpha=1";

TEST_F(StudyCommand, ManufacturedLadderWritesTableAndPictures) {
  ASSERT_EQ(study("--vary mesh.size=1/4,1/8,1/16 " + manufactured), 0) << err_;
  for (const char* file : {"study.csv", "study.png", "study.svg"})
    EXPECT_TRUE(fs::exists(output() / file)) << file;
  const std::string table = csv();
  EXPECT_EQ(table.rfind("key,value,parameter,dofs,", 0), 0u);
  EXPECT_NE(table.find("mesh.size,1/16,0.0625,"), std::string::npos) << table;
  EXPECT_NE(table.find(",converged,"), std::string::npos);
  // report.html: the same table and the plot inside the page.
  const std::string report = formflow::testing::read_text(output() / "report.html");
  EXPECT_NE(report.find("<th>key</th><th>value</th><th>parameter</th><th>dofs</th>"),
            std::string::npos);
  EXPECT_NE(report.find("<td class=\"number\">mesh.size</td><td class=\"number\">1/16</td>"),
            std::string::npos);
  const std::string picture = "src=\"data:image/svg+xml;base64,";
  const auto first = report.find(picture); // the study plot, and no corner plot here
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(report.find(picture, first + 1), std::string::npos);
  EXPECT_NE(report.find("all 3 rungs converged"), std::string::npos);
}

TEST_F(StudyCommand, BadInputWritesNothing) {
  EXPECT_EQ(study("--vary mesh.sise=1,0.5"), 2);
  EXPECT_NE(err_.find("did you mean `mesh.size`?"), std::string::npos) << err_;
  EXPECT_EQ(study("--vary mesh.element=1,2"), 2);
  EXPECT_NE(err_.find("numeric key"), std::string::npos) << err_;
  EXPECT_EQ(study("--vary mesh.size=1"), 2);
  EXPECT_NE(err_.find("at least two values"), std::string::npos) << err_;
  EXPECT_EQ(study("--vary mesh.size=1,0.3"), 2); // 0.3 does not fit the geometry
  EXPECT_NE(err_.find("mesh.size"), std::string::npos) << err_;
  EXPECT_EQ(study("--vary penalty.d=1e-3,x/2"), 2);
  EXPECT_EQ(study("--vary mesh.size=1,0.5 --set penalty.d=-1"), 2);
  EXPECT_FALSE(fs::exists(output()));
}

TEST_F(StudyCommand, NonConvergedRungGivesExitThreeAndIsMarked) {
  EXPECT_EQ(study("--vary mesh.size=2.5,5 --set solver.max_iterations=2"), 3);
  EXPECT_NE(err_.find("NOT CONVERGED"), std::string::npos) << err_;
  EXPECT_NE(csv().find(",max_iterations,"), std::string::npos) << csv();
  EXPECT_TRUE(fs::exists(output() / "study.png"));
}

} // namespace
