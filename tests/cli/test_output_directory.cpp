// SPDX-License-Identifier: MIT
// A -o that cannot take the results: exit 2 before the solve, a clear message, nothing written.
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace formflow::testing {
namespace {

namespace fs = std::filesystem;

class OutputDirectory : public ::testing::Test {
protected:
  /// `formflow run -o OUTPUT` on mesh I (a solve of a second or so, never reached here).
  CliResult run(const fs::path& output) {
    return run_cli("run --set mesh.size=2.5 -o " + quoted(output.string()), scratch_.path());
  }
  CliResult study(const fs::path& output) {
    return run_cli("study --vary mesh.size=5,2.5 -o " + quoted(output.string()), scratch_.path());
  }
  /// Exit 2, the path and `reason` in the message, no monitor line (the solve never started).
  static void expect_refused(const CliResult& result, const fs::path& path,
                             const std::string& reason) {
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_TRUE(has_text(result.err, "-o: " + path.string()));
    EXPECT_TRUE(has_text(result.err, reason));
    EXPECT_EQ(result.out.find("rel.change"), std::string::npos) << result.out;
  }
  ScratchDirectory scratch_{"formflow-output-directory"};
};

TEST_F(OutputDirectory, ARegularFileIsRefusedAndKept) {
  const fs::path file = scratch_ / "results.txt";
  std::ofstream(file) << "not a directory";
  expect_refused(run(file), file, "is a regular file, not a directory");
  expect_refused(study(file), file, "is a regular file, not a directory");
  EXPECT_EQ(read_text(file), "not a directory");
}

TEST_F(OutputDirectory, APathBelowAFileIsRefused) {
  const fs::path file = scratch_ / "results.txt";
  std::ofstream(file) << "x";
  const fs::path below = file / "run1";
  expect_refused(run(below), below, "cannot be created: " + file.string() + " is a regular file");
  EXPECT_EQ(read_text(file), "x");
}

TEST_F(OutputDirectory, ASummaryThatIsADirectoryIsRefusedAndNothingIsWritten) {
  const fs::path out = scratch_ / "out";
  fs::create_directories(out / "summary.json");
  expect_refused(run(out), out, "summary.json in it is a directory");
  EXPECT_TRUE(has_text(
      // The hint says what to do about it.
      run(out).err, "remove or rename " + (out / "summary.json").string()));
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 1);
  EXPECT_TRUE(fs::is_empty(out / "summary.json"));
  fs::create_directories(scratch_ / "ladder" / "study.csv");
  expect_refused(study(scratch_ / "ladder"), scratch_ / "ladder", "study.csv in it is a directory");
}

TEST_F(OutputDirectory, AnImpossibleOrUnwritablePathIsRefused) {
  // /proc takes no new entries, whoever runs the test (root ignores mode bits).
  expect_refused(run("/proc/formflow-results"), "/proc/formflow-results", "cannot be created");
  if (::geteuid() != 0) {
    const fs::path locked = scratch_ / "locked";
    fs::create_directories(locked);
    ::chmod(locked.c_str(), 0500);
    expect_refused(run(locked), locked, "formflow cannot create files in it");
    ::chmod(locked.c_str(), 0700);
  }
}

TEST_F(OutputDirectory, ABrokenLinkIsRefused) {
  const fs::path link = scratch_ / "dangling";
  fs::create_symlink(scratch_ / "nowhere", link);
  expect_refused(run(link), link, "is a broken symbolic link");
}

TEST_F(OutputDirectory, AMissingDirectoryIsCreatedWithTheResults) {
  const fs::path out = scratch_ / "new" / "nested";
  const CliResult result = run(out);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_TRUE(fs::exists(out / "fields.vtu"));
}

} // namespace
} // namespace formflow::testing
