// SPDX-License-Identifier: MIT
// Reading and checking a mesh file's bytes, and the private copy Gmsh reads instead.
#include "formflow/mesh/msh_file.hpp"

#include "formflow/mesh/gmsh_mesh.hpp"
#include "formflow/mesh/msh_data.hpp"
#include "formflow/mesh/msh_header.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <system_error>

namespace formflow::mesh {

namespace {

using Subject = MeshFileError::Subject;

[[noreturn]] void fail_copy(const std::string& what) {
  throw std::system_error(errno, std::generic_category(), "private copy of the mesh: " + what);
}

} // namespace

std::string read_msh_bytes(const std::string& path) {
  std::error_code code;
  if (!std::filesystem::exists(path, code))
    throw MeshFileError(Subject::File, "", "no such file: " + path,
                        "a relative mesh.file is taken from the case file's directory");
  if (!std::filesystem::is_regular_file(path, code))
    throw MeshFileError(Subject::File, "", "not a regular file: " + path, "give a .msh file");
  const auto size = std::filesystem::file_size(path, code);
  if (!code && size > max_msh_file_bytes)
    throw MeshFileError(Subject::File, "",
                        path + ": " + std::to_string(size) + " bytes, more than the limit of " +
                            std::to_string(max_msh_file_bytes),
                        "formflow's 2D meshes are far smaller: is this the right file?");
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream content;
  if (!stream || !(content << stream.rdbuf()))
    throw MeshFileError(Subject::File, "", "cannot read " + path, "check its permissions");
  std::string bytes = std::move(content).str();
  std::string problem;
  const std::optional<MshHeader> header = parse_msh_header(bytes, problem);
  if (!header)
    throw MeshFileError(Subject::File, "", path + ": " + problem,
                        std::string(msh_header_requirement));
  if (auto refusal = msh_data_problem(bytes, *header, path))
    throw MeshFileError(Subject::File, "", std::move(*refusal),
                        "a mesh as Gmsh writes it: counts the file holds, tags 1…n, finite "
                        "coordinates within ±1e12, each node once (docs/reliability.md)");
  return bytes;
}

PrivateMshCopy::PrivateMshCopy(const std::string& bytes) {
  std::string pattern = (std::filesystem::temp_directory_path() / "formflow-mesh-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) fail_copy("mkdtemp " + pattern);
  directory_ = pattern;
  const std::string file = path();
  const int descriptor =
      ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (descriptor < 0) {
    std::filesystem::remove_all(directory_);
    fail_copy("open " + file);
  }
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t step = ::write(descriptor, bytes.data() + written, bytes.size() - written);
    if (step < 0 && errno == EINTR) continue;
    if (step <= 0) {
      ::close(descriptor);
      std::filesystem::remove_all(directory_);
      fail_copy("write " + file);
    }
    written += static_cast<std::size_t>(step);
  }
  if (::close(descriptor) != 0) {
    std::filesystem::remove_all(directory_);
    fail_copy("close " + file);
  }
}

PrivateMshCopy::~PrivateMshCopy() {
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

} // namespace formflow::mesh
