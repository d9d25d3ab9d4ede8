// SPDX-License-Identifier: MIT
// The MSH data check against Gmsh: every file Gmsh writes (2.2 and 4.1, ASCII and
// binary, 2D and 3D) passes it, Gmsh reads the hand-written honest files the unit
// tests mutate, and each hostile file (cut tags, negative tags, absurd coordinates,
// counts the file cannot hold, a node twice) is exit 2 from `formflow run` naming the
// file, its line (or byte) and the bound, with nothing written.
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/die_face.hpp"
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/mesh/gmsh_session.hpp"
#include "formflow/mesh/gmsh_solid_mesh.hpp"
#include "formflow/mesh/msh_file.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"
#include "support/msh_writer.hpp"
#include "support/run_cli.hpp"

#include <fmt/format.h>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace formflow {
namespace {

namespace fs = std::filesystem;
using testing::has_text;
using testing::quoted;

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// Writes the current Gmsh model as `version`, ASCII or binary.
void write_as(const mesh::GmshSession& session, const fs::path& path, double version, bool binary) {
  session.call([&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::option::setNumber("Mesh.SaveAll", 1);
    gmsh::write(path.string());
  });
}

TEST(MshDataCheck, EveryFileGmshWritesPassesIt) {
  testing::ScratchDirectory scratch("formflow-msh-data");
  mesh::ChannelGeometry geometry;
  mesh::SolidChannel solid;
  solid.section = mesh::ChannelSection::Rectangle;
  solid.entry_half_width = 10;
  solid.exit_half_width = 5;
  int files = 0;
  for (const int dimension : {2, 3})
    for (const int order : {1, 2}) {
      mesh::GmshSession session;
      if (dimension == 2) {
        mesh::build_channel_model(session, geometry, mesh::square_die_face(geometry), 2.5, order);
      } else {
        session.call([] { gmsh::model::add("solid"); });
        mesh::add_solid_mesh_to_gmsh_model(
            session, mesh::make_solid_channel_mesh(geometry, solid, 5.0, order, false));
      }
      for (const double version : {2.2, 4.1})
        for (const bool binary : {false, true}) {
          const fs::path path =
              scratch / fmt::format("m{}{}{}{}.msh", dimension, order, version, binary ? "b" : "a");
          write_as(session, path, version, binary);
          EXPECT_GT(fs::file_size(path), 1000u) << path; // a real mesh, not an empty model
          EXPECT_NO_THROW(mesh::read_msh_bytes(path.string())) << path;
          ++files;
        }
    }
  EXPECT_EQ(files, 16);
}

TEST(MshDataCheck, GmshReadsTheHandWrittenHonestFiles) {
  // The hostile files below are these with one number changed: they are real MSH.
  testing::ScratchDirectory scratch("formflow-msh-data");
  for (const bool solid : {false, true})
    for (const std::string version : {"2.2", "4.1"})
      for (const bool binary : {false, true}) {
        const testing::MshContent content =
            solid ? testing::one_hexahedron() : testing::two_quads();
        const fs::path path = scratch / "honest.msh";
        write_bytes(path, testing::msh_bytes(content, version, binary));
        mesh::GmshSession session;
        std::vector<std::size_t> tags;
        std::vector<double> coordinates, parametric;
        session.call([&] {
          gmsh::open(path.string());
          gmsh::model::mesh::getNodes(tags, coordinates, parametric);
        });
        EXPECT_EQ(tags.size(), content.nodes.size()) << version << binary << solid;
        EXPECT_NO_THROW(mesh::read_msh_bytes(path.string()));
      }
}

/// Version, binary, 3D.
using Format = std::tuple<std::string, bool, bool>;

/// One hostile edit of the honest mesh and what the refusal must say.
struct Hostile {
  std::string name;
  std::function<void(testing::MshContent&)> edit;
  std::string words;  ///< in the message
  std::string token;  ///< the hostile number as written (its line, in ASCII)
  bool int_tags_only; ///< cannot be written in a 2.2 binary file (its tags are int)
};

std::vector<Hostile> hostile_edits(bool v41) {
  const std::int64_t big = std::int64_t{1} << 62, wrapped = (std::int64_t{1} << 32) + 5;
  auto tag = [v41](std::int64_t value) {
    // 4.1 declares its largest tag before the nodes: the lie is refused there.
    return v41 ? fmt::format("maximum tag {} is above", value)
               : fmt::format("node tag {} is above 2147483647", value);
  };
  return {
      {"tag 2^62", [big](auto& m) { m.nodes[2].tag = big; }, tag(big), std::to_string(big), true},
      {"tag 2^32+5", [wrapped](auto& m) { m.nodes[2].tag = wrapped; }, tag(wrapped),
       std::to_string(wrapped), true},
      {"negative tag", [](auto& m) { m.nodes[1].tag = -3; }, "-3", "-3", false},
      {"x = 1e308", [](auto& m) { m.nodes[3].x = 1e308; }, "x = 1e+308 is outside |x| ≤ 1e+12",
       "1e+308", false},
      {"x = 1e200", [](auto& m) { m.nodes[3].x = 1e200; }, "x = 1e+200 is outside |x| ≤ 1e+12",
       "1e+200", false},
      {"x = 1e30", [](auto& m) { m.nodes[3].x = 1e30; }, "x = 1e+30 is outside |x| ≤ 1e+12",
       "1e+30", false},
      {"1e9 nodes declared", [](auto& m) { m.declared_nodes = 1000000000; },
       "1000000000 nodes declared, but the", "1000000000", false},
      {"1e8 nodes declared", [](auto& m) { m.declared_nodes = 100000000; },
       "100000000 nodes declared, but the", "100000000", false},
      {"duplicate node", [](auto& m) { m.nodes[4].tag = 2; }, "node tag 2 is a duplicate", "",
       false},
  };
}

class HostileMshFile : public ::testing::TestWithParam<Format> {};

TEST_P(HostileMshFile, IsExitTwoNamingTheFileTheLineAndTheBoundWithNothingWritten) {
  const auto& [version, binary, solid] = GetParam();
  testing::ScratchDirectory scratch("formflow-msh-data");
  const fs::path case_path = scratch / "case.toml";
  std::ofstream(case_path) << "[mesh]\nsource = \"file\"\nelement = \"Q1\"\nfile = \"m.msh\"\n"
                           << (solid ? "[geometry]\ndimension = 3\n" : "");
  bool first = true; // `check` refuses as `run` does: once per format is enough
  for (const Hostile& hostile : hostile_edits(version == "4.1")) {
    if (hostile.int_tags_only && binary && version == "2.2") continue;
    SCOPED_TRACE(hostile.name);
    testing::MshContent content = solid ? testing::one_hexahedron() : testing::two_quads();
    hostile.edit(content);
    const std::string bytes = testing::msh_bytes(content, version, binary);
    write_bytes(scratch / "m.msh", bytes);
    std::vector<std::string> commands = {"run -q -o " + quoted((scratch / "out").string())};
    if (std::exchange(first, false)) commands.emplace_back("check");
    for (const std::string& command : commands) {
      const testing::CliResult result =
          testing::run_cli(command + " " + quoted(case_path.string()), scratch.path());
      EXPECT_EQ(result.exit_code, 2) << result.err;
      EXPECT_TRUE(has_text(result.err,
                           case_path.string() + ":4: mesh.file: " + (scratch / "m.msh").string()));
      EXPECT_TRUE(has_text(result.err, hostile.words));
      if (binary) {
        EXPECT_TRUE(has_text(result.err, "m.msh: byte "));
      } else if (!hostile.token.empty()) {
        const auto at = bytes.find(hostile.token);
        const auto line =
            1 + std::count(bytes.begin(), bytes.begin() + static_cast<long>(at), '\n');
        EXPECT_TRUE(has_text(result.err, fmt::format("m.msh:{}: ", line)));
      }
      EXPECT_FALSE(fs::exists(scratch / "out")) << "nothing may be written on bad input";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(, HostileMshFile,
                         ::testing::Combine(::testing::Values("2.2", "4.1"), ::testing::Bool(),
                                            ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) == "2.2" ? "v22" : "v41") +
                                  (std::get<1>(info.param) ? "_binary" : "_ascii") +
                                  (std::get<2>(info.param) ? "_3d" : "_2d");
                         });

} // namespace
} // namespace formflow
