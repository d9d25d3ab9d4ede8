// SPDX-License-Identifier: MIT
// Reading a .vtu text back with VTK's own reader (tests/support/read_vtu.py).
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace formflow::testing {

/// What VTK's reader saw in the file `path` (.vtu, or .pvtu with its pieces beside it);
/// fails the test if VTK cannot read it.
inline nlohmann::json read_file_with_vtk(const std::filesystem::path& path) {
  const auto errors = std::filesystem::path(path).replace_extension(".stderr");
  const std::string command = "/usr/bin/python3 " FORMFLOW_SOURCE_DIR
                              "/tests/support/read_vtu.py '" +
                              path.string() + "' 2>'" + errors.string() + "'";
  std::string output;
  int status = -1;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 65536> buffer;
    for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
      output.append(buffer.data(), n);
    status = ::pclose(pipe);
  }
  std::ifstream error_stream(errors);
  const std::string stderr_text((std::istreambuf_iterator<char>(error_stream)),
                                std::istreambuf_iterator<char>());
  std::filesystem::remove(errors);
  EXPECT_EQ(status, 0) << command << "\n" << stderr_text;
  if (status != 0) return nlohmann::json::object();
  return nlohmann::json::parse(output);
}

/// Writes `vtu` to a temporary file, reads it with /usr/bin/python3 + VTK
/// (the Python first on PATH cannot import Debian's python3-vtk9) and returns
/// what VTK saw. Fails the test if VTK cannot read it.
inline nlohmann::json read_with_vtk(const std::string& vtu, const std::string& name) {
  const auto directory = std::filesystem::temp_directory_path();
  const auto file = directory / ("formflow_" + name + "_" + std::to_string(::getpid()) + ".vtu");
  const auto errors = std::filesystem::path(file).replace_extension(".stderr");
  std::ofstream(file, std::ios::binary) << vtu;
  const std::string command = "/usr/bin/python3 " FORMFLOW_SOURCE_DIR
                              "/tests/support/read_vtu.py " +
                              file.string() + " 2>" + errors.string();
  std::string output;
  int status = -1;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 65536> buffer;
    for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
      output.append(buffer.data(), n);
    status = ::pclose(pipe);
  }
  std::ifstream error_stream(errors);
  const std::string stderr_text((std::istreambuf_iterator<char>(error_stream)),
                                std::istreambuf_iterator<char>());
  std::filesystem::remove(file);
  std::filesystem::remove(errors);
  EXPECT_EQ(status, 0) << command << "\n" << stderr_text;
  if (status != 0) return nlohmann::json::object();
  return nlohmann::json::parse(output);
}

} // namespace formflow::testing
