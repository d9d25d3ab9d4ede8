// SPDX-License-Identifier: MIT
// The MSH header check that stands between a user's file and Gmsh's script interpreter.
#include "formflow/mesh/msh_header.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

namespace formflow::mesh {
namespace {

std::optional<MshHeader> parse(const std::string& bytes, std::string& problem) {
  return parse_msh_header(bytes, problem);
}

/// The header Gmsh writes for a binary file, with `marker` as the 4 raw bytes.
std::string binary_header(const char* version, std::uint32_t marker) {
  std::string bytes = std::string("$MeshFormat\n") + version + " 1 8\n";
  char raw[4];
  std::memcpy(raw, &marker, 4);
  return bytes + std::string(raw, 4) + "\n$EndMeshFormat\n$Entities\n";
}

TEST(MshHeader, AcceptsTheFormatsGmshWrites) {
  std::string problem;
  for (const char* version : {"4.1", "2.2"}) {
    const auto ascii =
        parse(std::string("$MeshFormat\n") + version + " 0 8\n$EndMeshFormat\n$Nodes", problem);
    ASSERT_TRUE(ascii) << problem;
    EXPECT_EQ(ascii->version, version);
    EXPECT_FALSE(ascii->binary);
    const auto binary = parse(binary_header(version, 1), problem);
    ASSERT_TRUE(binary) << problem;
    EXPECT_TRUE(binary->binary);
  }
  // Written on a machine of the other byte order, and with Windows line ends.
  EXPECT_TRUE(parse(binary_header("4.1", 0x01000000u), problem)) << problem;
  EXPECT_TRUE(parse("$MeshFormat\r\n4.1 0 8\r\n$EndMeshFormat\r\n", problem)) << problem;
}

TEST(MshHeader, RefusesAScriptWhateverItsName) {
  std::string problem;
  EXPECT_FALSE(parse("SystemCall \"touch /tmp/x\";\n", problem));
  EXPECT_NE(problem.find("not a Gmsh MSH file"), std::string::npos) << problem;
  // Nothing of a file that is not a mesh is quoted: it may be anyone's secret.
  EXPECT_EQ(problem.find("SystemCall"), std::string::npos) << problem;
  EXPECT_NE(problem.find("its first line is not `$MeshFormat`"), std::string::npos) << problem;
  // A script with the header's first line but no header after it.
  EXPECT_FALSE(parse("$MeshFormat\nSystemCall \"touch /tmp/x\";\n", problem));
  EXPECT_NE(problem.find("unsupported MSH format line"), std::string::npos) << problem;
  // Leading blanks or a comment before the header: not what Gmsh writes.
  EXPECT_FALSE(parse(" $MeshFormat\n4.1 0 8\n$EndMeshFormat\n", problem));
  EXPECT_FALSE(parse("// mesh\n$MeshFormat\n4.1 0 8\n$EndMeshFormat\n", problem));
}

TEST(MshHeader, RefusesOtherVersionsTypesAndSizes) {
  std::string problem;
  for (const char* line : {"4.0 0 8", "3 0 8", "2.1 0 8", "4.1 2 8", "4.1 0 4", "4.1  0 8",
                           "4.1 0 8 extra", "4.1 0", ""}) {
    SCOPED_TRACE(line);
    EXPECT_FALSE(parse(std::string("$MeshFormat\n") + line + "\n$EndMeshFormat\n", problem));
    EXPECT_NE(problem.find("unsupported MSH format line"), std::string::npos) << problem;
  }
}

TEST(MshHeader, RefusesTruncatedOrBrokenHeaders) {
  std::string problem;
  EXPECT_FALSE(parse("", problem));
  EXPECT_EQ(problem, "the file is empty");
  EXPECT_FALSE(parse("$MeshFormat", problem)); // no newline
  EXPECT_FALSE(parse("$MeshFormat\n4.1 0 8", problem));
  EXPECT_FALSE(parse("$MeshFormat\n4.1 0 8\n$Nodes\n", problem));
  EXPECT_NE(problem.find("$EndMeshFormat"), std::string::npos) << problem;
  // Binary: the marker missing, cut short, or not the int 1.
  EXPECT_FALSE(parse("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n", problem));
  EXPECT_FALSE(parse("$MeshFormat\n4.1 1 8\n\x01\x00", problem));
  EXPECT_FALSE(parse(binary_header("4.1", 2), problem));
  EXPECT_NE(problem.find("marker"), std::string::npos) << problem;
}

} // namespace
} // namespace formflow::mesh
