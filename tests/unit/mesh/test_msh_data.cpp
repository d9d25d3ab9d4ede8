// SPDX-License-Identifier: MIT
// The data check of an MSH file's sections (mesh/msh_data.hpp): Gmsh's own files and
// honest hand-written ones pass in formats 2.2 and 4.1, ASCII and binary, 2D and 3D;
// lying counts, cut tags, absurd coordinates and repeated nodes are refused with
// their place and bound, without allocating by the lie.
#include "formflow/mesh/msh_data.hpp"
#include "formflow/mesh/msh_header.hpp"
#include "support/msh_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>

namespace formflow::mesh {
namespace {

using testing::MshContent;

/// msh_data_problem of `bytes`, whose header must pass; "" when the data passes.
std::string problem_of(const std::string& bytes) {
  std::string header_problem;
  const auto header = parse_msh_header(bytes, header_problem);
  EXPECT_TRUE(header) << header_problem;
  if (!header) return header_problem;
  return msh_data_problem(bytes, *header, "m.msh").value_or("");
}

/// The line (1-based) of the first `token` in `text`, as "m.msh:LINE: ".
std::string place_of(const std::string& text, const std::string& token) {
  const std::size_t at = text.find(token);
  EXPECT_NE(at, std::string::npos) << token;
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  return "m.msh:" + std::to_string(line) + ": ";
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream content;
  content << stream.rdbuf();
  return content.str();
}

TEST(MshData, TheFilesGmshWroteForTheTestsAndCasesPass) {
  const std::filesystem::path source(FORMFLOW_SOURCE_DIR);
  int files = 0;
  for (const auto& folder : {source / "tests" / "data" / "meshes", source / "cases" / "meshes"})
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".msh") {
        EXPECT_EQ(problem_of(read_file(entry.path())), "") << entry.path();
        ++files;
      }
  EXPECT_GE(files, 8);
}

/// Every format: version, binary, the other byte order, 3D.
using Format = std::tuple<std::string, bool, bool, bool>;

class MshDataFormats : public ::testing::TestWithParam<Format> {
protected:
  MshContent honest() const {
    return std::get<3>(GetParam()) ? testing::one_hexahedron() : testing::two_quads();
  }
  std::string bytes(const MshContent& mesh) const {
    const Format& format = GetParam();
    return testing::msh_bytes(mesh, std::get<0>(format), std::get<1>(format), std::get<2>(format));
  }
  bool binary() const { return std::get<1>(GetParam()); }
  bool v41() const { return std::get<0>(GetParam()) == "4.1"; }
  /// Refused, naming `words`, and in ASCII the line of `token`.
  void expect_refused(const MshContent& mesh, const std::string& words,
                      const std::string& token) const {
    const std::string text = bytes(mesh);
    const std::string problem = problem_of(text);
    EXPECT_NE(problem.find(words), std::string::npos) << problem;
    if (binary())
      EXPECT_EQ(problem.rfind("m.msh: byte ", 0), 0u) << problem;
    else
      EXPECT_EQ(problem.rfind(place_of(text, token), 0), 0u) << problem;
  }
};

TEST_P(MshDataFormats, AnHonestMeshPasses) {
  EXPECT_EQ(problem_of(bytes(honest())), "");
}

TEST_P(MshDataFormats, NodeTagsGmshWouldCutAreRefused) {
  for (const std::int64_t tag :
       {std::int64_t{1} << 62, (std::int64_t{1} << 32) + 3, std::int64_t{2147483648}}) {
    MshContent mesh = honest();
    mesh.nodes[2].tag = tag;
    // 2.2 binary stores an int: such a tag cannot be written there (the writer would
    // cut it); its negative tags are NegativeAndZeroTagsAreRefused's.
    if (!v41() && binary()) continue;
    // 4.1 declares its largest tag first: the lie is refused there.
    expect_refused(mesh,
                   v41() ? fmt::format("maximum tag {} is above", tag)
                         : fmt::format("node tag {} is above 2147483647", tag),
                   std::to_string(tag));
    if (!v41()) continue;
    mesh.declared_last_node = static_cast<std::int64_t>(mesh.nodes.size());
    expect_refused(mesh, fmt::format("node tag {} is above 2147483647", tag),
                   std::to_string(tag) + "\n");
  }
}

TEST_P(MshDataFormats, NegativeAndZeroTagsAreRefused) {
  MshContent mesh = honest();
  mesh.nodes[1].tag = -3;
  // A 4.1 binary file stores tags as size_t: -3 reads as 2^64 − 3.
  expect_refused(mesh,
                 binary() && v41() ? "(-3 as a signed number) is above 2147483647"
                                   : "tag -3 is not positive", // 4.1: the declared minimum
                 "-3");
  mesh = honest();
  mesh.elements[0].tag = 0;
  const std::string problem = problem_of(bytes(mesh));
  EXPECT_NE(problem.find("tag 0 is not positive"), std::string::npos) << problem;
}

TEST_P(MshDataFormats, TagsBeyondWhatTheCountsCanHoldAreRefused) {
  // 6 or 8 nodes may use tags up to 16 · n + 1024; 4.1 also declares its maximum.
  MshContent mesh = honest();
  mesh.nodes.back().tag = 5000;
  const std::string problem = problem_of(bytes(mesh));
  EXPECT_NE(problem.find("5000 is above"), std::string::npos) << problem;
  EXPECT_NE(problem.find("16 × count + 1024"), std::string::npos) << problem;
  mesh = honest();
  mesh.elements[0].nodes[0] = std::int64_t{1} << 40; // cut to 0 by a 2.2 binary int
  const std::string reference = problem_of(bytes(mesh));
  EXPECT_NE(reference.find(binary() && !v41() ? "names node 0, outside 1…2147483647"
                                              : "names node 1099511627776, outside 1…2147483647"),
            std::string::npos)
      << reference;
}

TEST_P(MshDataFormats, AbsurdCoordinatesAreRefused) {
  for (const double x : {1e308, 1e200, 1e30, -2e12, 4.9e-324}) {
    MshContent mesh = honest();
    mesh.nodes[3].x = x;
    expect_refused(mesh, x == 4.9e-324 ? "is subnormal" : "is outside |x| ≤ 1e+12",
                   fmt::format("{}", x));
  }
  MshContent mesh = honest();
  mesh.nodes[3].y = std::numeric_limits<double>::infinity();
  EXPECT_NE(problem_of(bytes(mesh)).find("y is not finite"), std::string::npos);
  mesh = honest();
  mesh.nodes[3].z = 1e12; // the bound itself is allowed
  EXPECT_EQ(problem_of(bytes(mesh)), "");
}

TEST_P(MshDataFormats, ARepeatedNodeTagIsNamedADuplicate) {
  MshContent mesh = honest();
  mesh.nodes[4].tag = mesh.nodes[1].tag;
  const std::string problem = problem_of(bytes(mesh));
  EXPECT_NE(problem.find(fmt::format("node tag {} is a duplicate", mesh.nodes[1].tag)),
            std::string::npos)
      << problem;
}

TEST_P(MshDataFormats, CountsTheFileCannotHoldAreRefusedWithoutAllocating) {
  // A file of a few hundred bytes declaring 10^9 or 10^8 nodes: refused by arithmetic,
  // at once (an allocation by the count would throw bad_alloc or take gigabytes).
  for (const std::int64_t declared : {std::int64_t{1000000000}, std::int64_t{100000000}}) {
    MshContent mesh = honest();
    mesh.declared_nodes = declared;
    const auto start = std::chrono::steady_clock::now();
    expect_refused(mesh, fmt::format("{} nodes declared, but the", declared),
                   std::to_string(declared));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  }
  MshContent more = honest();
  more.declared_nodes = static_cast<std::int64_t>(more.nodes.size()) + 1;
  EXPECT_NE(problem_of(bytes(more)), "");
}

TEST_P(MshDataFormats, ATruncatedFileIsRefused) {
  const std::string text = bytes(honest());
  for (const std::size_t cut : {text.size() / 2, text.size() - 4, text.size() - 12})
    EXPECT_NE(problem_of(text.substr(0, cut)), "") << cut;
}

std::string format_name(const ::testing::TestParamInfo<Format>& info) {
  const Format& format = info.param;
  return std::string(std::get<0>(format) == "2.2" ? "v22" : "v41") +
         (std::get<1>(format) ? "_binary" : "_ascii") + (std::get<2>(format) ? "_swapped" : "") +
         (std::get<3>(format) ? "_3d" : "_2d");
}

INSTANTIATE_TEST_SUITE_P(
    , MshDataFormats,
    ::testing::Values(Format{"2.2", false, false, false}, Format{"2.2", true, false, false},
                      Format{"2.2", true, true, false}, Format{"4.1", false, false, false},
                      Format{"4.1", true, false, false}, Format{"4.1", true, true, false},
                      Format{"2.2", false, false, true}, Format{"2.2", true, false, true},
                      Format{"4.1", false, false, true}, Format{"4.1", true, false, true},
                      Format{"4.1", true, true, true}),
    format_name);

TEST(MshData, SectionsOtherThanAMeshsAreRefused) {
  const std::string honest = testing::msh_bytes(testing::two_quads(), "4.1", false);
  const std::string header = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  const std::string body = honest.substr(header.size());
  EXPECT_NE(problem_of(header + "$NodeData\n1\n$EndNodeData\n" + body).find("m.msh:4: section "),
            std::string::npos);
  EXPECT_NE(problem_of(honest + "$Nodes\n0 0 0 0\n$EndNodes\n").find("a second `$Nodes`"),
            std::string::npos);
  EXPECT_NE(problem_of(header + "SystemCall \"x\";\n" + body).find("text outside a section"),
            std::string::npos);
  std::string unknown_type = honest;
  unknown_type.replace(unknown_type.find("\n2 1 3 2\n"), 9, "\n2 1 99 2\n");
  EXPECT_NE(problem_of(unknown_type).find("element type 99 is not one of Gmsh's types"),
            std::string::npos)
      << problem_of(unknown_type);
}

TEST(MshData, ASectionEndsWhereItsCountsSay) {
  // One node more than declared: the count says the section is over.
  std::string text = testing::msh_bytes(testing::two_quads(), "2.2", false);
  text.replace(text.find("$EndNodes"), 9, "7 3 0 0\n$EndNodes");
  EXPECT_NE(problem_of(text).find("`$EndNodes` expected here"), std::string::npos)
      << problem_of(text);
}

} // namespace
} // namespace formflow::mesh
