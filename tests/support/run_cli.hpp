// SPDX-License-Identifier: MIT
// Running the formflow binary from a test, and the small file helpers around it:
// one copy for tests/cli, tests/gmsh and tests/unit/io.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace formflow::testing {

/// The whole file as bytes; "" if it cannot be read.
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

/// `text` in single quotes, one word for /bin/sh (the paths of the tests hold no quote).
inline std::string quoted(const std::string& text) {
  return "'" + text + "'";
}

/// Success when `text` contains `part`; the failure message shows both.
inline ::testing::AssertionResult has_text(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

/// A fresh, empty directory under the system temp dir, named after `prefix`, the
/// running test and the process (parallel ctest runs do not collide); removed
/// with its contents when this object goes.
class ScratchDirectory {
public:
  explicit ScratchDirectory(const std::string& prefix) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test = info ? std::string(info->name()) : std::string("no-test");
    path_ = std::filesystem::temp_directory_path() /
            (prefix + "-" + test + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
  std::filesystem::path path_;
};

/// What one run of the binary did.
struct CliResult {
  int exit_code = -1; ///< -1 when it did not exit normally (a signal)
  std::string out;    ///< stdout
  std::string err;    ///< stderr
};

/// Runs `formflow ARGUMENTS` (ARGUMENTS already shell-quoted) through /bin/sh,
/// from `working_directory` when given, with stdout and stderr captured through
/// files in `scratch`.
inline CliResult run_cli(const std::string& arguments, const std::filesystem::path& scratch,
                         const std::filesystem::path& working_directory = {}) {
  const std::filesystem::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  std::string command = quoted(FORMFLOW_BINARY) + " " + arguments + " > " + quoted(out.string()) +
                        " 2> " + quoted(err.string());
  if (!working_directory.empty())
    command = "cd " + quoted(working_directory.string()) + " && " + command;
  const int status = std::system(command.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}

} // namespace formflow::testing
