// SPDX-License-Identifier: MIT
// A user's .msh file handed to Gmsh as data only: checked bytes in a private copy.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace formflow::mesh {

/// Largest mesh file read, in bytes: it is read into memory whole, and 1 GiB of
/// ASCII MSH is some 10 million quadrilaterals, more than a 2D run's memory check
/// admits on any machine of ours.
inline constexpr std::uintmax_t max_msh_file_bytes = std::uintmax_t{1} << 30;

/// The whole content of the mesh file `path`, read once. Throws MeshFileError
/// (Subject::File) when it is missing, not a regular file, unreadable, or not
/// an MSH file by parse_msh_header, its sections not data by msh_data_problem, or
/// larger than max_msh_file_bytes — before any library has read it.
std::string read_msh_bytes(const std::string& path);

/// A copy of already checked MSH bytes in a fresh directory only this process
/// can use (mkdtemp, mode 0700; the file created with O_EXCL | O_NOFOLLOW),
/// removed with the object. Gmsh is given this copy, never the user's path:
/// Gmsh also runs `<file>.opt` beside a file it opens as a script, and the
/// user's file could change between the check and the read; neither can
/// happen to the copy.
class PrivateMshCopy {
public:
  explicit PrivateMshCopy(const std::string& bytes);
  ~PrivateMshCopy();
  PrivateMshCopy(const PrivateMshCopy&) = delete;
  PrivateMshCopy& operator=(const PrivateMshCopy&) = delete;

  /// The copy's path, ending in ".msh" so that Gmsh reads it as a mesh.
  std::string path() const { return (directory_ / "mesh.msh").string(); }

private:
  std::filesystem::path directory_;
};

} // namespace formflow::mesh
