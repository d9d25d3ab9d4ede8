// SPDX-License-Identifier: MIT
// A strict reader of the three or four lines of an MSH file's MeshFormat section.
#include "formflow/mesh/msh_header.hpp"

#include "formflow/core/printable_text.hpp"

#include <cstdint>
#include <cstring>
#include <vector>

namespace formflow::mesh {

namespace {

/// Reads one line ending in "\n" (a "\r" before it is dropped) from `bytes` at
/// `at`; false when there is no newline.
bool take_line(std::string_view bytes, std::size_t& at, std::string_view& line) {
  const std::size_t end = bytes.find('\n', at);
  if (end == std::string_view::npos) return false;
  line = bytes.substr(at, end - at);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  at = end + 1;
  return true;
}

/// The words of `line` separated by single spaces (Gmsh writes "%g %d %d").
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> result;
  while (!line.empty()) {
    const std::size_t space = line.find(' ');
    result.push_back(line.substr(0, space));
    if (space == std::string_view::npos) break;
    line.remove_prefix(space + 1);
  }
  return result;
}

std::string shown(std::string_view text) {
  std::string quoted(1, '`'); // built in place: GCC 12 warns (-Wrestrict) on "`" + string&&
  quoted += printable_text(text, 60);
  return quoted += '`';
}

} // namespace

std::optional<MshHeader> parse_msh_header(std::string_view bytes, std::string& problem) {
  std::size_t at = 0;
  std::string_view line;
  if (!take_line(bytes, at, line) || line != "$MeshFormat") {
    // Nothing of the file is quoted: mesh.file may name any readable file (a key, a
    // password file), and the error would show its first bytes to whoever reads it.
    problem = bytes.empty() ? "the file is empty"
                            : "not a Gmsh MSH file: its first line is not `$MeshFormat` (its "
                              "content is not shown)";
    return std::nullopt;
  }
  if (!take_line(bytes, at, line)) {
    problem = "the MSH header ends after `$MeshFormat`";
    return std::nullopt;
  }
  const std::vector<std::string_view> fields = words(line);
  if (fields.size() != 3 || (fields[0] != "4.1" && fields[0] != "2.2") ||
      (fields[1] != "0" && fields[1] != "1") || fields[2] != "8") {
    problem = "unsupported MSH format line " + shown(line) +
              " (formflow reads versions 4.1 and 2.2, file type 0 or 1, data size 8)";
    return std::nullopt;
  }
  MshHeader header{std::string(fields[0]), fields[1] == "1"};
  if (header.binary) {
    // The int 1 in the writer's byte order, then a newline.
    if (bytes.size() < at + 5 || bytes[at + 4] != '\n') {
      problem = "the binary MSH header lacks its 4-byte marker line after " + shown(line);
      return std::nullopt;
    }
    std::uint32_t marker = 0;
    std::memcpy(&marker, bytes.data() + at, 4);
    if (marker != 1u && marker != 0x01000000u) {
      problem = "the binary MSH header's marker is not the int 1 in either byte order";
      return std::nullopt;
    }
    at += 5;
  }
  std::string_view end_line;
  if (!take_line(bytes, at, end_line) || end_line != "$EndMeshFormat") {
    problem =
        "the MSH header does not end with `$EndMeshFormat` after the format line " + shown(line);
    return std::nullopt;
  }
  return header;
}

} // namespace formflow::mesh
