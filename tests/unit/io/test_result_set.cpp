// SPDX-License-Identifier: MIT
// A result set is published whole or not at all: stop requests, write failures, links, directories.
#include "formflow/io/output_error.hpp"
#include "formflow/io/result_set.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace formflow::testing {
namespace {

namespace fs = std::filesystem;

/// Every entry of `directory` with its contents ("<dir>" for a directory,
/// "-> target" for a link): two snapshots compare equal only if nothing changed.
std::map<std::string, std::string> snapshot(const fs::path& directory) {
  std::map<std::string, std::string> entries;
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_symlink())
      entries[name] = "-> " + fs::read_symlink(entry.path()).string();
    else if (entry.is_directory())
      entries[name] = "<dir>";
    else
      entries[name] = read_text(entry.path());
  }
  return entries;
}

bool has_staging(const fs::path& directory) {
  for (const auto& entry : fs::directory_iterator(directory))
    if (entry.path().filename().string().starts_with(io::staging_prefix)) return true;
  return false;
}

class ResultSet : public ::testing::Test {
protected:
  void SetUp() override {
    new_set_ = {{"history.csv", "new history"},
                {"fields.vtu", std::string(20000, 'v')},
                {"summary.json", "{\"converged\": true, \"new\": true}"}};
  }
  /// An older run's set, with a file the new set does not have and a user's own file.
  void write_old_set() const {
    fs::create_directories(out());
    for (const char* name : {"summary.json", "history.csv", "fields.vtu", "corner.csv"})
      std::ofstream(out() / name) << "old " << name;
    std::ofstream(out() / "notes.txt") << "the user's";
  }
  fs::path out() const { return scratch_ / "out"; }
  void publish(const StopRequested& stop = {}) const {
    io::publish_result_set(out(), new_set_, "summary.json", known_, stop);
  }

  ScratchDirectory scratch_{"formflow-result-set"};
  std::vector<io::ResultFile> new_set_;
  std::vector<std::string> known_ = {"summary.json", "history.csv", "fields.vtu", "corner.csv"};
};

TEST_F(ResultSet, PublishesEveryFileRemovesStaleOnesAndKeepsTheUsersOwn) {
  write_old_set();
  publish();
  const auto seen = snapshot(out());
  EXPECT_EQ(seen, (std::map<std::string, std::string>{{"history.csv", "new history"},
                                                      {"fields.vtu", std::string(20000, 'v')},
                                                      {"summary.json", new_set_[2].contents},
                                                      {"notes.txt", "the user's"}}));
}

TEST_F(ResultSet, CreatesAMissingDirectory) {
  io::publish_result_set(scratch_ / "a" / "b", new_set_, "summary.json", known_);
  EXPECT_EQ(snapshot(scratch_ / "a" / "b").size(), 3u);
}

TEST_F(ResultSet, StopRequestAtAnySafePointLeavesTheOldSetAsItWas) {
  write_old_set();
  const auto before = snapshot(out());
  // Safe points: before the first file, between files, before the commit.
  for (std::size_t allowed = 0; allowed <= new_set_.size() + 1; ++allowed) {
    std::size_t asked = 0;
    EXPECT_THROW(publish([&] { return asked++ >= allowed; }), Stopped) << allowed;
    EXPECT_EQ(snapshot(out()), before) << "stopped after " << allowed << " answers";
  }
}

TEST_F(ResultSet, WriteFailureLeavesTheOldSetAsItWas) {
  // A real failing write(2), no seam: a file-size limit (RLIMIT_FSIZE) of 4 KiB
  // makes fields.vtu (20 kB) fail with EFBIG, as a full disk fails with ENOSPC.
  // In a child process, so that the limit and SIGXFSZ stay out of the test runner.
  write_old_set();
  const auto before = snapshot(out());
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      publish();
    } catch (const io::OutputError& error) {
      const std::string text = error.what();
      ::_exit(text.find("fields.vtu") != std::string::npos &&
                      text.find("too large") != std::string::npos
                  ? 0
                  : 2);
    } catch (...) {
      ::_exit(3);
    }
    ::_exit(1); // no error at all
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no error, 2: the message lacks the file or reason";
  EXPECT_EQ(snapshot(out()), before);
}

TEST_F(ResultSet, DirectoryInTheWayIsRefusedAndKept) {
  write_old_set();
  fs::remove(out() / "fields.vtu");
  fs::create_directory(out() / "fields.vtu");
  std::ofstream(out() / "fields.vtu" / "inside") << "the user's data";
  const auto before = snapshot(out());
  EXPECT_THROW(publish(), io::OutputError);
  EXPECT_EQ(snapshot(out()), before);
  EXPECT_EQ(read_text(out() / "fields.vtu" / "inside"), "the user's data");
}

TEST_F(ResultSet, DirectoryAppearingBeforeTheCommitRollsEveryFileBack) {
  // The last safe point comes after the check for directories in the way: a
  // directory made there is met inside the commit, which must undo its renames.
  write_old_set();
  fs::remove(out() / "fields.vtu");
  const auto before_directory = snapshot(out());
  std::size_t asked = 0;
  auto plant_directory = [&] {
    if (++asked == new_set_.size() + 2) {
      fs::create_directory(out() / "fields.vtu");
      std::ofstream(out() / "fields.vtu" / "inside") << "the user's data";
    }
    return false;
  };
  EXPECT_THROW(publish(plant_directory), io::OutputError);
  auto after = snapshot(out());
  EXPECT_EQ(after.at("fields.vtu"), "<dir>");
  EXPECT_EQ(read_text(out() / "fields.vtu" / "inside"), "the user's data");
  after.erase("fields.vtu");
  EXPECT_EQ(after, before_directory); // the old summary, history and corner files are back
}

TEST_F(ResultSet, LinksPlantedAtTheOldTemporaryNamesAreNotFollowed) {
  // Issue 14 item 7: temporaries used to be `<name>.tmp.<pid>` beside the target.
  fs::create_directories(out());
  const fs::path victim = scratch_ / "victim.txt";
  std::ofstream(victim) << "precious";
  for (const auto& file : new_set_)
    fs::create_symlink(victim, out() / (file.name + ".tmp." + std::to_string(::getpid())));
  publish();
  EXPECT_EQ(read_text(victim), "precious");
  for (const auto& file : new_set_) {
    EXPECT_FALSE(fs::is_symlink(out() / file.name)) << file.name;
    EXPECT_EQ(read_text(out() / file.name), file.contents) << file.name;
  }
}

TEST_F(ResultSet, StagingDirectoryIsPrivateAndGoneAfterwards) {
  fs::perms staging_permissions = fs::perms::unknown;
  std::size_t asked = 0;
  auto look = [&] {
    if (++asked == 2) // after the first file: the staging directory exists
      for (const auto& entry : fs::directory_iterator(out()))
        if (entry.path().filename().string().starts_with(io::staging_prefix))
          staging_permissions = entry.status().permissions();
    return false;
  };
  publish(look);
  EXPECT_EQ(staging_permissions, fs::perms::owner_all); // mkdtemp's 0700
  EXPECT_FALSE(has_staging(out()));
}

} // namespace
} // namespace formflow::testing
