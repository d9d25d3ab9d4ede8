// SPDX-License-Identifier: MIT
// Checking a CAD file before it is read (mesh/cad_file.hpp).
#include "formflow/mesh/cad_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace formflow::mesh {

namespace {

/// A die channel's solid is a few surfaces: files above this are no die.
constexpr std::uintmax_t max_cad_bytes = 256u << 20;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

} // namespace

CadFileCheck check_cad_file(const std::string& path) {
  CadFileCheck check;
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    check.problem = fmt::format("\"{}\" is not a readable regular file", path);
    check.hint = "give the path of a STEP (.step, .stp) or BREP (.brep) file of the die "
                 "channel's solid (relative to the case file)";
    return check;
  }
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error || bytes > max_cad_bytes) {
    check.problem = fmt::format("\"{}\" is larger than 256 MB: no die channel's solid", path);
    check.hint = "export the channel's solid alone";
    return check;
  }
  const std::string extension = lower(std::filesystem::path(path).extension().string());
  const bool step = extension == ".step" || extension == ".stp";
  const bool brep = extension == ".brep" || extension == ".brp";
  if (!step && !brep) {
    check.problem =
        fmt::format("\"{}\" is not a STEP or BREP file (extension \"{}\")", path, extension);
    check.hint = "export the die channel's solid as STEP (.step, .stp) or BREP (.brep)";
    return check;
  }
  std::ifstream stream(path, std::ios::binary);
  std::string head(64, '\0');
  stream.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(stream.gcount(), 0)));
  // A UTF-8 byte order mark and leading blank lines are allowed before the first line.
  std::size_t start = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  while (start < head.size() && std::isspace(static_cast<unsigned char>(head[start]))) ++start;
  const std::string first = head.substr(start);
  const bool step_header = first.rfind("ISO-10303-21;", 0) == 0;
  const bool brep_header =
      first.rfind("DBRep_DrawableShape", 0) == 0 || first.rfind("CASCADE Topology", 0) == 0;
  if (step ? !step_header : !brep_header) {
    check.problem = fmt::format("\"{}\" does not begin like a {} file", path,
                                step ? "STEP (ISO-10303-21;)" : "BREP (CASCADE Topology)");
    check.hint = "export the die channel's solid from the CAD program again (AP203/AP214 STEP, "
                 "or OpenCASCADE BREP)";
    return check;
  }
  check.format = step ? CadFormat::Step : CadFormat::Brep;
  return check;
}

} // namespace formflow::mesh
