// SPDX-License-Identifier: MIT
// Atomic writes: complete file or none, and never a stray temporary.
#include "formflow/io/atomic_file.hpp"

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
  bool wrote_something = false;
  EXPECT_THROW(io::write_file_atomically(directory_ / "broken.csv",
                                         [&](std::ostream& stream) {
                                           stream << "iteration,relative_change\n1,0.5\n";
                                           stream.flush();
                                           // The temporary really exists with data at this point.
                                           wrote_something =
                                               std::filesystem::file_size(io::temporary_path(
                                                   directory_ / "broken.csv")) > 0;
                                           throw std::runtime_error("solver exploded");
                                         }),
               std::runtime_error);
  EXPECT_TRUE(wrote_something);
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

TEST_F(AtomicFile, TemporaryNameIsBesideTheTargetWithThePid) {
  const auto temporary = io::temporary_path(directory_ / "fields.vtu");
  EXPECT_EQ(temporary.parent_path(), directory_);
  EXPECT_EQ(temporary.filename().string(), "fields.vtu.tmp." + std::to_string(::getpid()));
}

} // namespace
} // namespace formflow::testing
