// SPDX-License-Identifier: MIT
// The mesh source keys: mesh.source, mesh.file, [mesh.boundaries] and their cross-key checks.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_keys.hpp"
#include "support/run_cli.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace formflow::io {
namespace {

namespace fs = std::filesystem;

class MeshKeys : public ::testing::Test {
protected:
  std::string write(const std::string& text) {
    const fs::path path = directory_ / "case.toml";
    std::ofstream(path) << text;
    return path.string();
  }

  /// The InputError of loading `text`, checked to be at `key` on `line`.
  InputError error_in(const std::string& text, const std::string& key, int line) {
    const std::string path = write(text);
    try {
      load_case(path, {});
    } catch (const InputError& error) {
      EXPECT_EQ(error.key, key) << error.what();
      EXPECT_EQ(error.line, line) << error.what();
      return error;
    }
    ADD_FAILURE() << "no InputError for\n" << text;
    return InputError("", -1, "", "");
  }

  testing::ScratchDirectory directory_{"formflow-meshkeys"};
};

TEST_F(MeshKeys, DefaultsAreTheStructuredGenerator) {
  const Case case_ = load_case("", {});
  EXPECT_EQ(case_.mesh.source, mesh::MeshSource::Structured);
  EXPECT_TRUE(case_.mesh.file.empty());
  EXPECT_TRUE(case_.mesh.boundaries.empty());
}

TEST_F(MeshKeys, FileSourceReadsTheMapAndRemembersEachEntrysLine) {
  const Case case_ = load_case(write("[mesh]\nsource = \"file\"\nfile = \"die.msh\"\n"
                                     "[mesh.boundaries]\nram = \"rear\"\n\"die face\" = \"die\"\n"),
                               {});
  EXPECT_EQ(case_.mesh.source, mesh::MeshSource::File);
  EXPECT_EQ(case_.mesh.file, "die.msh");
  EXPECT_EQ(case_.mesh.boundaries, (NameMap{{"ram", "rear"}, {"die face", "die"}}));
  EXPECT_EQ(case_.key_locations.at("mesh.file").line, 3);
  EXPECT_EQ(case_.key_locations.at("mesh.boundaries.ram").line, 5);
  EXPECT_EQ(case_.key_locations.at("mesh.boundaries.die face").line, 6);
}

TEST_F(MeshKeys, FileSourceNeedsAFile) {
  const InputError error =
      error_in("[mesh]\nelement = \"Q1\"\nsource = \"file\"\n", "mesh.source", 3);
  EXPECT_NE(std::string(error.what()).find("needs mesh.file"), std::string::npos);
}

TEST_F(MeshKeys, FileOrMapWithoutFileSourceIsAMistake) {
  error_in("[mesh]\nfile = \"die.msh\"\n", "mesh.file", 2);
  error_in("[mesh]\nsource = \"gmsh\"\n[mesh.boundaries]\nram = \"rear\"\n", "mesh.boundaries", 3);
}

TEST_F(MeshKeys, PartNamesAreChecked) {
  const InputError error =
      error_in("[mesh]\nsource = \"file\"\nfile = \"a.msh\"\n[mesh.boundaries]\nram = \"ram\"\n",
               "mesh.boundaries", 5);
  EXPECT_NE(error.hint.find("\"rear\", \"free_entry\", \"container\", \"die\", \"free_exit\", "
                            "\"front\", \"symmetry\""),
            std::string::npos)
      << error.hint;
  const InputError type_error =
      error_in("[mesh]\nsource = \"file\"\nfile = \"a.msh\"\n[mesh.boundaries]\nram = 1\n",
               "mesh.boundaries", 5);
  EXPECT_NE(std::string(type_error.what()).find("entry \"ram\": expected a string, got integer 1"),
            std::string::npos)
      << type_error.what();
}

TEST_F(MeshKeys, BadPartNameIsBlamedOnItsOwnLineNotOnTheTableHeader) {
  // The header is line 4; the bad entry, after two good ones, is line 7.
  const InputError error = error_in("[mesh]\nsource = \"file\"\nfile = \"a.msh\"\n"
                                    "[mesh.boundaries]\nram = \"rear\"\naxis = \"symmetry\"\n"
                                    "wall = \"contianer\"\nexit = \"front\"\n",
                                    "mesh.boundaries", 7);
  EXPECT_NE(std::string(error.what()).find("invalid value \"contianer\" for \"wall\""),
            std::string::npos)
      << error.what();
  // Two bad entries: the first in the file is the one named.
  error_in("[mesh]\nsource = \"file\"\nfile = \"a.msh\"\n[mesh.boundaries]\nb = \"rear\"\n"
           "z = \"x\"\na = \"y\"\n",
           "mesh.boundaries", 6);
}

TEST_F(MeshKeys, GmshSourceTakesAnySizeButTheStructuredGridDoesNot) {
  // Gmsh meshes any size; the uniform grid needs a size that divides every length.
  EXPECT_EQ(load_case(write("[mesh]\nsource = \"gmsh\"\nsize = 0.7\n"), {}).mesh.size, 0.7);
  error_in("[mesh]\nsize = 0.7\n", "mesh.size", 2);
}

TEST_F(MeshKeys, MapCanBeSetOnTheCommandLine) {
  const Case case_ = load_case(
      "",
      {{"mesh.source", "file"}, {"mesh.file", "x.msh"}, {"mesh.boundaries", "{ram = \"rear\"}"}});
  EXPECT_EQ(case_.mesh.boundaries, (NameMap{{"ram", "rear"}}));
  EXPECT_EQ(case_.key_locations.at("mesh.boundaries.ram").file, "--set");
}

} // namespace
} // namespace formflow::io
