// SPDX-License-Identifier: MIT
// Atomic writes: complete file or none, and never a stray temporary.
#include "formflow/io/atomic_file.hpp"
#include "formflow/io/output_error.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

namespace formflow::testing {
namespace {

class AtomicFile : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ =
        std::filesystem::temp_directory_path() /
        ("formflow_atomic_" + std::string(test->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(directory_))
      names.insert(entry.path().filename().string());
    return names;
  }
  static std::string contents(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  }

  std::filesystem::path directory_;
};

TEST_F(AtomicFile, WritesTheContentsAndNothingElse) {
  const std::string bytes("binary\0data\n", 12);
  io::write_file_atomically(directory_ / "out.bin", bytes);
  EXPECT_EQ(contents(directory_ / "out.bin"), bytes);
  EXPECT_EQ(entries(), std::set<std::string>{"out.bin"});
}

TEST_F(AtomicFile, ReplacesAnExistingFile) {
  io::write_file_atomically(directory_ / "a.txt", "old contents, longer than the new");
  io::write_file_atomically(directory_ / "a.txt", "new");
  EXPECT_EQ(contents(directory_ / "a.txt"), "new");
  EXPECT_EQ(entries(), std::set<std::string>{"a.txt"});
}

TEST_F(AtomicFile, WriterThrowingMidwayLeavesNoFileAndNoTemporary) {
  EXPECT_THROW(io::write_file_atomically(directory_ / "broken.csv",
                                         [&](std::ostream& stream) {
                                           stream << "iteration,relative_change\n1,0.5\n";
                                           throw std::runtime_error("solver exploded");
                                         }),
               std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(directory_ / "broken.csv"));
  EXPECT_TRUE(entries().empty());
}

TEST_F(AtomicFile, WriterThrowingKeepsThePreviousFile) {
  io::write_file_atomically(directory_ / "summary.json", "{\"previous\": true}\n");
  EXPECT_THROW(io::write_file_atomically(directory_ / "summary.json",
                                         [](std::ostream& stream) {
                                           stream << "{\"half";
                                           throw std::logic_error("bug");
                                         }),
               std::logic_error);
  EXPECT_EQ(contents(directory_ / "summary.json"), "{\"previous\": true}\n");
  EXPECT_EQ(entries(), std::set<std::string>{"summary.json"});
}

TEST_F(AtomicFile, MissingDirectoryThrowsAndCreatesNothing) {
  EXPECT_THROW(io::write_file_atomically(directory_ / "missing" / "x.txt", "x"),
               std::runtime_error);
  EXPECT_TRUE(entries().empty());
}

// Issue 14 item 7: the temporary used to be `<name>.tmp.<pid>`, opened without
// O_EXCL/O_NOFOLLOW, so a link planted there made formflow overwrite its target.
TEST_F(AtomicFile, LinkPlantedAtThePredictableTemporaryNameIsNotFollowed) {
  const auto victim = directory_ / "victim.txt";
  { std::ofstream(victim) << "precious"; }
  const auto planted = directory_ / ("fields.vtu.tmp." + std::to_string(::getpid()));
  std::filesystem::create_symlink(victim, planted);
  io::write_file_atomically(directory_ / "fields.vtu", "new fields");
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_EQ(contents(directory_ / "fields.vtu"), "new fields");
  EXPECT_FALSE(std::filesystem::is_symlink(directory_ / "fields.vtu"));
  EXPECT_TRUE(std::filesystem::is_symlink(planted)); // left alone, not replaced or followed
  EXPECT_EQ(entries(), (std::set<std::string>{"fields.vtu", "victim.txt", planted.filename()}));
}

TEST_F(AtomicFile, NewFileRefusesALinkAtItsNameAndLeavesItsTargetAlone) {
  const auto victim = directory_ / "victim.txt";
  { std::ofstream(victim) << "precious"; }
  std::filesystem::create_symlink(victim, directory_ / "summary.json");
  const int fd = ::open(directory_.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(fd, 0);
  EXPECT_THROW(io::write_new_file(fd, "summary.json", "{}", directory_ / "summary.json"),
               io::OutputError);
  ::close(fd);
  EXPECT_EQ(contents(victim), "precious");
  EXPECT_TRUE(std::filesystem::is_symlink(directory_ / "summary.json"));
}

} // namespace
} // namespace formflow::testing
