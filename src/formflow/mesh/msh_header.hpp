// SPDX-License-Identifier: MIT
// Recognising a Gmsh MSH file by its header before any library reads it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace formflow::mesh {

/// The MeshFormat section of an MSH file.
struct MshHeader {
  std::string version; ///< "2.2" or "4.1", as written
  bool binary = false;
};

/// Gmsh opens any file that is not a mesh as a .geo script, which can run
/// shell commands (SystemCall), write files (Printf > file) and read others
/// (Merge): a user's file must be proven a mesh before Gmsh sees it.
///
/// Parses the start of `bytes` as the header Gmsh writes:
///
///     $MeshFormat
///     VERSION FILE-TYPE DATA-SIZE
///     [the int 1 as 4 raw bytes, then a newline: binary files only]
///     $EndMeshFormat
///
/// with VERSION 2.2 or 4.1, FILE-TYPE 0 (ASCII) or 1 (binary), DATA-SIZE 8,
/// and lines ended by "\n" or "\r\n". The binary marker may be in either byte
/// order (Gmsh swaps). Returns the header, or sets `problem` to what is wrong
/// (one sentence; it quotes no byte of a file whose first line is not
/// `$MeshFormat`, which may be any readable file) and returns std::nullopt. Only the
/// header is read: `bytes` may be the first few hundred bytes of the file.
std::optional<MshHeader> parse_msh_header(std::string_view bytes, std::string& problem);

/// What is valid, for the hint of an error about a file that is not MSH.
inline constexpr std::string_view msh_header_requirement =
    "a Gmsh mesh: the file must start with `$MeshFormat`, then `4.1 0 8` or `2.2 0 8` "
    "(ASCII) or `4.1 1 8` / `2.2 1 8` (binary), then `$EndMeshFormat` (gmsh -save -format "
    "msh41, or msh22)";

} // namespace formflow::mesh
