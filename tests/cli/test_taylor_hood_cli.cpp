// SPDX-License-Identifier: MIT
// formulation.pressure = "Q1" (Taylor–Hood) runs from the command line; the
// combinations that cannot work are still refused with exit 2 and no output.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string err;
};

class TaylorHoodCli : public ::testing::Test {
protected:
  void SetUp() override {
    scratch_ = fs::temp_directory_path() /
               ("formflow-th-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
                std::to_string(getpid()));
    fs::remove_all(scratch_);
    fs::create_directories(scratch_);
  }
  void TearDown() override { fs::remove_all(scratch_); }

  /// `formflow run` on the default case with `settings` (--set k=v ...), output to results/.
  CliRun run(const std::string& settings) const {
    const fs::path err = scratch_ / "stderr.txt";
    const std::string command = std::string("'") + FORMFLOW_BINARY + "' run -q -o '" +
                                (scratch_ / "results").string() + "' " + settings +
                                " > /dev/null 2> '" + err.string() + "'";
    const int status = std::system(command.c_str());
    CliRun result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream stream(err);
    std::ostringstream text;
    text << stream.rdbuf();
    result.err = text.str();
    return result;
  }
  bool wrote_results() const { return fs::exists(scratch_ / "results" / "summary.json"); }

  fs::path scratch_;
};

constexpr const char* taylor_hood =
    "--set formulation.type=mixed --set formulation.pressure=Q1 --set process.ram=sticking "
    "--set mesh.size=2.5 ";

TEST_F(TaylorHoodCli, RunsWithExactConstraintsAndWritesEveryResult) {
  const CliRun result = run(std::string(taylor_hood) + "--set penalty.d=0 --set penalty.dN=0");
  EXPECT_EQ(result.exit_code, 0) << result.err;
  for (const char* file :
       {"summary.json", "fields.vtu", "contact.csv", "history.csv", "pressure.png"})
    EXPECT_TRUE(fs::exists(scratch_ / "results" / file)) << file;
}

TEST_F(TaylorHoodCli, RefusedCombinationsExitTwoAndWriteNothing) {
  for (const std::string extra :
       {"--set mesh.element=Q1", "--set friction.regularization=none --set friction.mu=0.1"}) {
    const CliRun result = run(std::string(taylor_hood) + extra);
    EXPECT_EQ(result.exit_code, 2) << extra << ": " << result.err;
    EXPECT_FALSE(wrote_results()) << extra;
    EXPECT_NE(result.err.find("--set"), std::string::npos) << result.err;
  }
}

} // namespace
