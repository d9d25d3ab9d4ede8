// SPDX-License-Identifier: MIT
// SIGINT/SIGTERM during a solve or a study, a full disk, a file-size limit: exit
// 130/143 or 1, no staging directory left, the previous results exactly as they were.
#include "support/run_cli.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace formflow::testing {
namespace {

namespace fs = std::filesystem;

/// Every entry of `directory` with its contents: equal snapshots, nothing changed.
std::map<std::string, std::string> snapshot(const fs::path& directory) {
  std::map<std::string, std::string> entries;
  for (const auto& entry : fs::directory_iterator(directory))
    entries[entry.path().filename().string()] =
        entry.is_directory() ? "<dir>" : read_text(entry.path());
  return entries;
}

/// A previous run's results, recognisable byte for byte.
void write_previous_results(const fs::path& directory, const std::vector<std::string>& names) {
  fs::create_directories(directory);
  for (const std::string& name : names) std::ofstream(directory / name) << "previous " << name;
}

/// Starts `formflow ARGUMENTS...` with stdout and stderr into files; sends
/// `signal` once stdout holds `ready` (the solve is under way), then waits.
/// Returns the exit code (-1 if it died of a signal) or -2 if `ready` never came.
int run_and_signal(const std::vector<std::string>& arguments, const fs::path& scratch,
                   const std::string& ready, int signal) {
  const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const pid_t child = ::fork();
  if (child == 0) {
    const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out_fd, 1);
    ::dup2(err_fd, 2);
    std::vector<char*> argv{const_cast<char*>(FORMFLOW_BINARY)};
    for (const std::string& argument : arguments)
      argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    ::execv(FORMFLOW_BINARY, argv.data());
    ::_exit(127);
  }
  bool sent = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  while (::waitpid(child, &status, WNOHANG) == 0) {
    if (!sent && read_text(out).find(ready) != std::string::npos) {
      ::kill(child, signal);
      sent = true;
    }
    if (std::chrono::steady_clock::now() > deadline) ::kill(child, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!sent) return -2;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A solve of many iterations: the secant loop on mesh II to a tolerance it
/// needs hundreds of iterations for (a second per few dozen here).
const std::vector<std::string> slow_run = {"run",
                                           "--set",
                                           "solver.method=secant",
                                           "--set",
                                           "solver.tolerance=1e-12",
                                           "--set",
                                           "solver.max_iterations=100000"};

class InterruptedRun : public ::testing::TestWithParam<int> {
protected:
  fs::path out() const { return scratch_ / "out"; }
  ScratchDirectory scratch_{"formflow-interrupted"};
};

TEST_P(InterruptedRun, SignalDuringTheSolveExitsCleanlyAndKeepsThePreviousResults) {
  write_previous_results(out(), {"summary.json", "fields.vtu", "history.csv"});
  const auto before = snapshot(out());
  std::vector<std::string> arguments = slow_run;
  arguments.insert(arguments.end(), {"-o", out().string()});
  // "    2  " is the monitor line of the second iteration: the solve is running.
  const int code = run_and_signal(arguments, scratch_.path(), "\n    2  ", GetParam());
  EXPECT_EQ(code, 128 + GetParam()) << read_text(scratch_ / "stderr.txt");
  EXPECT_TRUE(has_text(read_text(scratch_ / "stderr.txt"), "stopped by a signal"));
  EXPECT_EQ(snapshot(out()), before); // no staging directory, no new file
}

TEST_P(InterruptedRun, SignalDuringTheErrorEstimateStopsItThere) {
  // The sticking ram at h = 1 (mesh II: no 2h) takes the refined estimate: a settle on
  // 5 042 dofs, the third level on h/4 and the doubled regularisations' solve, each
  // iteration a safe point. Stopped in it, the run writes nothing; had the estimate run
  // to its end first, the results would be written before the signal was seen.
  write_previous_results(out(), {"summary.json", "fields.vtu", "history.csv"});
  const auto before = snapshot(out());
  // δ = 1e-10 makes the levels after the settle take about a second (they solve to δ):
  // time for the signal to arrive inside the estimate on a loaded machine too.
  const std::vector<std::string> arguments = {"run",
                                              "--set",
                                              "process.ram=sticking",
                                              "--set",
                                              "mesh.element=Q2",
                                              "--set",
                                              "solver.tolerance=1e-10",
                                              "-o",
                                              out().string()};
  const int code = run_and_signal(arguments, scratch_.path(), "-- error estimate: ", GetParam());
  EXPECT_EQ(code, 128 + GetParam()) << read_text(scratch_ / "stderr.txt");
  EXPECT_TRUE(has_text(read_text(scratch_ / "stderr.txt"), "stopped by a signal during the solve"))
      << read_text(scratch_ / "stderr.txt");
  EXPECT_EQ(snapshot(out()), before);
}

TEST_P(InterruptedRun, SignalDuringAStudyExitsCleanlyAndKeepsThePreviousStudy) {
  write_previous_results(out(), {"study.csv", "study.png"});
  const auto before = snapshot(out());
  const std::vector<std::string> arguments = {"study",
                                              "--vary",
                                              "mesh.size=1,0.5",
                                              "--set",
                                              "solver.method=secant",
                                              "--set",
                                              "solver.tolerance=1e-12",
                                              "--set",
                                              "solver.max_iterations=100000",
                                              "-o",
                                              out().string()};
  // The header line is printed before the first rung starts.
  const int code = run_and_signal(arguments, scratch_.path(), "formflow study of", GetParam());
  EXPECT_EQ(code, 128 + GetParam()) << read_text(scratch_ / "stderr.txt");
  EXPECT_EQ(snapshot(out()), before);
}

INSTANTIATE_TEST_SUITE_P(Signals, InterruptedRun, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& info) {
                           return std::string(info.param == SIGINT ? "SIGINT" : "SIGTERM");
                         });

TEST(FailedWrite, FileSizeLimitLeavesThePreviousResultsAndSaysWhy) {
  // `ulimit -f` (RLIMIT_FSIZE, 64 blocks of 512 bytes) fails the write of fields.vtu
  // (hundreds of kB) with EFBIG, the way a full disk fails it with ENOSPC.
  const ScratchDirectory scratch("formflow-fsize");
  const fs::path out = scratch / "out";
  write_previous_results(out, {"summary.json", "fields.vtu"});
  const auto before = snapshot(out);
  const fs::path err = scratch / "stderr.txt";
  const std::string command = "ulimit -f 64; exec " + quoted(FORMFLOW_BINARY) +
                              " run -q --set mesh.size=0.5 -o " + quoted(out.string()) + " 2> " +
                              quoted(err.string());
  const int status = std::system(("sh -c " + quoted(command)).c_str());
  ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal: SIGXFSZ not ignored?";
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string message = read_text(err);
  EXPECT_TRUE(has_text(message, "cannot write the results"));
  EXPECT_TRUE(has_text(message, "File too large"));
  EXPECT_TRUE(has_text(message, "left as it was"));
  EXPECT_EQ(snapshot(out), before);
}

TEST(FailedWrite, FullDiskLeavesThePreviousResultsAndSaysWhy) {
  // A real ENOSPC: a 256 KiB tmpfs, mounted only where the test may (root with CAP_SYS_ADMIN).
  const ScratchDirectory scratch("formflow-full-disk");
  const fs::path disk = scratch / "disk";
  fs::create_directories(disk);
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=256k") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here (needs root): " << std::strerror(errno);
  struct Unmount {
    fs::path path;
    ~Unmount() { ::umount2(path.c_str(), MNT_DETACH); }
  } unmount{disk};
  const fs::path out = disk / "out";
  write_previous_results(out, {"summary.json", "fields.vtu", "history.csv"});
  const auto before = snapshot(out);
  const CliResult result =
      run_cli("run -q --set mesh.size=0.5 -o " + quoted(out.string()), scratch.path());
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(has_text(result.err, "No space left on device"));
  EXPECT_EQ(snapshot(out), before);
}

} // namespace
} // namespace formflow::testing
