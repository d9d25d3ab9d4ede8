// SPDX-License-Identifier: MIT
// mesh.source = "file" through the binary: a good .msh is accepted; each defect
// is exit 2 with file:line, key and a hint, and nothing is written.
#include "gmsh/gmsh_test_mesh.hpp"

#include "support/run_cli.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using testing::has_text;
using testing::quoted;
using testing::read_text;

/// The boundary map of two_squares(), as lines 6–10 of the case file.
const std::string full_map = "[mesh.boundaries]\n"
                             "ram = \"rear\"\n"
                             "axis = \"symmetry\"\n"
                             "front = \"front\"\n"
                             "wall = \"container\"\n";

class MeshFile : public ::testing::Test {
protected:
  MeshFile() { fs::create_directories(scratch_ / "meshes"); }

  /// Writes `mesh` to meshes/m.msh and a case that reads it (mesh.file relative
  /// to the case file: line 4; [mesh.boundaries] from line 6); runs `formflow
  /// run` into out/; returns the exit code and keeps stderr.
  int run_with(const testing::TestMesh& mesh, const std::string& element = "Q1",
               const std::string& boundaries = full_map, const std::string& file = "meshes/m.msh") {
    testing::write_test_mesh(mesh, (scratch_ / "meshes" / "m.msh").string());
    const fs::path case_path = scratch_ / "case.toml";
    std::ofstream(case_path) << "[mesh]\n"
                             << "source = \"file\"\n"
                             << "element = \"" << element << "\"\n"
                             << "file = \"" << file << "\"\n"
                             << "\n"
                             << boundaries;
    const testing::CliResult result =
        testing::run_cli("run " + quoted(case_path.string()) + " -q -o " +
                             quoted((scratch_ / "out").string()) + extra_arguments_,
                         scratch_.path());
    error_ = result.err;
    return result.exit_code;
  }

  /// Exit 2, the case file and line, the key, and no output directory.
  void expect_input_error(int code, int line, const std::string& key, const std::string& words) {
    EXPECT_EQ(code, 2) << error_;
    EXPECT_TRUE(has_text(error_, (scratch_ / "case.toml").string() + ":" + std::to_string(line) +
                                     ": " + key + ": "));
    EXPECT_TRUE(has_text(error_, words));
    EXPECT_FALSE(fs::exists(scratch_ / "out")) << "nothing may be written on bad input";
  }

  testing::ScratchDirectory scratch_{"formflow-meshfile"};
  std::string error_;
  std::string extra_arguments_; ///< appended to the command line (e.g. " --set k=v")
};

TEST_F(MeshFile, AGoodMeshIsSolved) {
  // Two Q1 cells pushed by the ram under a frictionless wall: converges (exit 0).
  EXPECT_EQ(run_with(testing::two_squares()), 0) << error_;
  ASSERT_TRUE(fs::exists(scratch_ / "out" / "summary.json"));
  // summary.json describes the mesh read, not the structured mesh.size key.
  const auto mesh = nlohmann::json::parse(read_text(scratch_ / "out" / "summary.json")).at("mesh");
  EXPECT_EQ(mesh.at("source"), "file");
  EXPECT_EQ(mesh.at("elements"), 2);
  EXPECT_TRUE(mesh.at("size").is_null());
  EXPECT_DOUBLE_EQ(mesh.at("min_cell_diameter").get<double>(), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(mesh.at("max_cell_diameter").get<double>(), std::sqrt(2.0));
}

TEST_F(MeshFile, TheShippedCaseReadsItsMeshRelativeToTheCaseFile) {
  // Run from the scratch directory: mesh.file must be found next to the case file, not in cwd.
  const fs::path case_path = fs::path(FORMFLOW_SOURCE_DIR) / "cases" / "wedge-die-msh.toml";
  const testing::CliResult result =
      testing::run_cli("check " + quoted(case_path.string()), scratch_.path(), scratch_.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(has_text(result.out + result.err, "valid (240 cells, 1025 nodes)"));
}

TEST_F(MeshFile, MissingFile) {
  const int code = run_with(testing::two_squares(), "Q1", full_map, "meshes/absent.msh");
  expect_input_error(code, 4, "mesh.file", "no such file");
}

TEST_F(MeshFile, MappedGroupAbsentFromTheFile) {
  const int code = run_with(testing::two_squares(), "Q1", full_map + "die = \"die\"\n");
  expect_input_error(code, 11, "mesh.boundaries.die", "no physical group named \"die\"");
  EXPECT_TRUE(has_text(error_, "physical curves in the mesh: axis, front, ram, wall"));
}

TEST_F(MeshFile, MappedGroupOfAnotherDimension) {
  // "domain" is the file's physical surface: a plane mesh's boundary parts are curves.
  const int code = run_with(testing::two_squares(), "Q1", full_map + "domain = \"die\"\n");
  expect_input_error(code, 11, "mesh.boundaries.domain",
                     "physical group \"domain\" is of dimension 2, not a curve");
  EXPECT_TRUE(has_text(error_, "physical curves in the mesh: axis, front, ram, wall"));
}

TEST_F(MeshFile, UnmappedGroupOnTheBoundary) {
  const std::string without_front =
      "[mesh.boundaries]\nram = \"rear\"\naxis = \"symmetry\"\nwall = \"container\"\n";
  const int code = run_with(testing::two_squares(), "Q1", without_front);
  expect_input_error(code, 6, "mesh.boundaries", "physical curve \"front\" lies on the boundary");
  EXPECT_TRUE(has_text(error_, "add `\"front\" = PART` to [mesh.boundaries]"));
}

TEST_F(MeshFile, BoundaryFacetWithoutLabel) {
  testing::TestMesh mesh = testing::two_squares();
  mesh.curves.erase(mesh.curves.begin() + 2); // no "front" group at all
  const std::string without_front =
      "[mesh.boundaries]\nram = \"rear\"\naxis = \"symmetry\"\nwall = \"container\"\n";
  const int code = run_with(mesh, "Q1", without_front);
  expect_input_error(
      code, 6, "mesh.boundaries",
      "1 boundary facets are in no mapped physical curve, e.g. the segment (2, 0)–(2, 1)");
}

TEST_F(MeshFile, Triangles) {
  testing::TestMesh mesh = testing::two_squares();
  mesh.element_type = 2;
  mesh.elements = {{1, 2, 5}, {1, 5, 4}, {2, 3, 6}, {2, 6, 5}};
  // The quadrilaterals' default meets a file of triangles: mesh.cell is the key to change
  // (left at its default, the error stands at mesh.file's line).
  const int code = run_with(mesh);
  expect_input_error(code, 4, "mesh.cell", "4 elements of type \"Triangle 3\"");
  EXPECT_TRUE(has_text(error_, "set mesh.cell = \"triangle\""));
}

TEST_F(MeshFile, TrianglesAreSolvedWithMeshCellTriangle) {
  testing::TestMesh mesh = testing::two_squares();
  mesh.element_type = 2;
  mesh.elements = {{1, 2, 5}, {1, 5, 4}, {2, 3, 6}, {2, 6, 5}};
  extra_arguments_ = " --set mesh.cell=triangle";
  EXPECT_EQ(run_with(mesh, "P1b"), 0) << error_;
  const auto summary = nlohmann::json::parse(read_text(scratch_ / "out" / "summary.json"));
  EXPECT_EQ(summary.at("mesh").at("elements"), 4);
  // The ram pushes through x = 0 and the metal leaves at x = 2: summary.json's exit.
  const auto& exit = summary.at("exit");
  EXPECT_LE(exit.at("velocity").at("min").get<double>(),
            exit.at("velocity").at("mean").get<double>());
  EXPECT_LE(exit.at("velocity").at("mean").get<double>(),
            exit.at("velocity").at("max").get<double>());
  EXPECT_TRUE(exit.contains("nonuniformity") && exit.contains("flux_balance"));
  // The other element order than the file's blames mesh.element, in triangles' words.
  fs::remove_all(scratch_ / "out");
  expect_input_error(run_with(mesh, "P2"), 3, "mesh.element",
                     "mesh.element = \"P2\" needs 6-node triangles; the mesh has 3-node ones");
}

TEST_F(MeshFile, SerendipityQuadrilaterals) {
  testing::TestMesh mesh = testing::two_squares();
  mesh.element_type = 16; // quad-8: corners, then mid-edge nodes
  mesh.nodes.insert(mesh.nodes.end(),
                    {{0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}, {1.5, 0}, {2, 0.5}, {1.5, 1}});
  mesh.elements = {{1, 2, 5, 4, 7, 8, 9, 10}, {2, 3, 6, 5, 11, 12, 13, 8}};
  const int code = run_with(mesh, "Q2");
  expect_input_error(code, 3, "mesh.element",
                     "8-node serendipity quadrilaterals are not supported");
}

TEST_F(MeshFile, OrderDifferentFromMeshElement) {
  const int code = run_with(testing::two_squares(), "Q2");
  expect_input_error(code, 3, "mesh.element",
                     "mesh.element = \"Q2\" needs 9-node quadrilaterals; the mesh has 4-node ones");
}

TEST_F(MeshFile, TangledElement) {
  testing::TestMesh mesh = testing::two_squares();
  // Node 4 pulled across the opposite edge: the first cell crosses itself
  // (same connectivity and boundary), so its Jacobian changes sign inside.
  mesh.nodes[3] = {1.5, 0.3};
  const int code = run_with(mesh);
  expect_input_error(code, 4, "mesh.file",
                     "cell 0 (centre (0.875, 0.325)) is inverted, tangled or degenerate");
}

TEST_F(MeshFile, DrivenEndMissing) {
  // Every facet labelled, but none is the rear that the extrusion ram pushes.
  const std::string no_rear = "[mesh.boundaries]\nram = \"symmetry\"\naxis = \"symmetry\"\n"
                              "front = \"front\"\nwall = \"container\"\n";
  const int code = run_with(testing::two_squares(), "Q1", no_rear);
  expect_input_error(code, 6, "mesh.boundaries", "no boundary facet is \"rear\"");
}

TEST_F(MeshFile, InvalidPartName) {
  // Blamed on the entry's own line (11), not on the [mesh.boundaries] header (6).
  const int code = run_with(testing::two_squares(), "Q1", full_map + "extra = \"wall\"\n");
  expect_input_error(code, 11, "mesh.boundaries", "invalid value \"wall\" for \"extra\"");
  EXPECT_TRUE(has_text(error_, "\"rear\", \"free_entry\", \"container\""));
}

TEST_F(MeshFile, CollapsedEdgeIsRefusedBeforeTheSolve) {
  // Node 4 moved onto node 1: the first cell's left edge has length 0. Its
  // Jacobian vanishes along that edge only, so every Gauss point passed the
  // check and the solve failed with "internal error"; the corners do not pass.
  testing::TestMesh mesh = testing::two_squares();
  mesh.nodes[3] = {0, 0};
  const int code = run_with(mesh);
  expect_input_error(code, 4, "mesh.file", "not positive at a node (a collapsed edge");
}

/// A mesh file is data: a script in its place is refused before Gmsh sees it,
/// whatever its name, and nothing it asks for happens.
class MeshFileIsData : public MeshFile {
protected:
  /// The marker file the hostile scripts below try to create.
  fs::path marker() const { return scratch_ / "marker"; }
  std::string script() const {
    return "SystemCall \"touch " + marker().string() + "\";\nPrintf(\"x\") > \"" +
           marker().string() + "\";\n";
  }
  /// Runs `formflow COMMAND case.toml` with case.toml reading `mesh_name` (line 4).
  int run_command(const std::string& command, const std::string& mesh_name) {
    const fs::path case_path = scratch_ / "case.toml";
    std::ofstream(case_path) << "[mesh]\nsource = \"file\"\nelement = \"Q1\"\nfile = \""
                             << mesh_name << "\"\n\n"
                             << full_map;
    const std::string output =
        command == "run" ? " -q -o " + quoted((scratch_ / "out").string()) : std::string();
    const testing::CliResult result =
        testing::run_cli(command + " " + quoted(case_path.string()) + output, scratch_.path());
    error_ = result.err;
    return result.exit_code;
  }
};

TEST_F(MeshFileIsData, AScriptNamedMshIsNotRun) {
  // Before: `formflow check` ran the SystemCall (the marker existed afterwards).
  for (const std::string command : {"check", "run"})
    for (const std::string name : {"meshes/die.msh", "meshes/die.geo", "meshes/die"}) {
      SCOPED_TRACE(command + " " + name);
      std::ofstream(scratch_ / name) << script();
      expect_input_error(run_command(command, name), 4, "mesh.file", "not a Gmsh MSH file");
      EXPECT_TRUE(has_text(error_, "`$MeshFormat`"));
      EXPECT_FALSE(fs::exists(marker())) << "the script ran";
    }
}

TEST_F(MeshFileIsData, AHeaderWithAScriptAfterItIsRefused) {
  std::ofstream(scratch_ / "meshes" / "m.msh") << "$MeshFormat\n" << script();
  expect_input_error(run_command("check", "meshes/m.msh"), 4, "mesh.file",
                     "unsupported MSH format line");
  EXPECT_FALSE(fs::exists(marker()));
}

TEST_F(MeshFileIsData, AReadableFileThatIsNotAMeshIsNotQuoted) {
  // mesh.file may name any readable file: the error says what is wrong with it without
  // showing a byte of it (it used to echo the first 60).
  const std::string secret = "root:$6$FORMFLOWSECRET$hash:19000:0:99999:7:::";
  for (const std::string& content : {secret + "\n", secret,
                                     "\x7f"
                                     "ELF\x02\x01" +
                                         secret})
    for (const std::string command : {"check", "run"}) {
      std::ofstream(scratch_ / "meshes" / "shadow", std::ios::binary) << content;
      expect_input_error(run_command(command, "meshes/shadow"), 4, "mesh.file",
                         "not a Gmsh MSH file: its first line is not `$MeshFormat`");
      EXPECT_FALSE(has_text(error_, "FORMFLOWSECRET")) << error_;
      EXPECT_FALSE(has_text(error_, "root:")) << error_;
      EXPECT_FALSE(has_text(error_, "ELF")) << error_;
    }
}

TEST_F(MeshFileIsData, ANulInTheMeshPathIsRefusedByKey) {
  // The path would end at the NUL for every file call, reading meshes/m.msh instead of
  // the name written (case file line 4, or --set).
  testing::write_test_mesh(testing::two_squares(), (scratch_ / "meshes" / "m.msh").string());
  expect_input_error(run_command("check", "meshes/m.msh\\u0000.txt"), 4, "mesh.file",
                     "contains a NUL byte (at byte 12)");
  extra_arguments_ = " --set 'mesh.file=\"meshes/m.msh\\u0000.txt\"'";
  EXPECT_EQ(run_with(testing::two_squares()), 2) << error_;
  EXPECT_TRUE(has_text(error_, "--set: mesh.file: contains a NUL byte")) << error_;
  EXPECT_FALSE(fs::exists(scratch_ / "out"));
}

TEST_F(MeshFileIsData, AnOptionFileBesideTheMeshIsNotRun) {
  // Gmsh runs `<file>.opt` as a script after opening <file>: it is given a private copy.
  testing::write_test_mesh(testing::two_squares(), (scratch_ / "meshes" / "m.msh").string());
  std::ofstream(scratch_ / "meshes" / "m.msh.opt") << script();
  EXPECT_EQ(run_command("check", "meshes/m.msh"), 0) << error_;
  EXPECT_FALSE(fs::exists(marker())) << "the .opt file ran";
}

} // namespace
} // namespace formflow
