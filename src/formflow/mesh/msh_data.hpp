// SPDX-License-Identifier: MIT
// The body of an MSH file checked as data before Gmsh reads it: counts the file can
// hold, tags Gmsh can keep, coordinates a solve can use, no node given twice.
#pragma once

#include "formflow/mesh/msh_header.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace formflow::mesh {

/// Largest node or element tag: Gmsh's reader keeps tags as `int` and cuts larger ones.
inline constexpr std::uint64_t max_msh_tag = 2147483647; // 2^31 − 1

/// A section of n entries may use tags up to sparse_tag_factor · n + sparse_tag_slack:
/// Gmsh's tag caches are indexed by tag, so a tag costs memory by its size, and this
/// keeps that below the cost of the entries themselves (the files Gmsh writes number
/// 1…n; meshes with unsaved entities leave gaps of a few times n at most).
inline constexpr std::uint64_t sparse_tag_factor = 16;
inline constexpr std::uint64_t sparse_tag_slack = 1024;

/// Largest |coordinate|: the case keys' lengths are at most 1e6, and every scale a
/// solve forms from coordinates (areas, volumes, Jacobians ~ x³) stays a finite,
/// normal double up to here, with room for a mesh in other units (μm).
inline constexpr double max_msh_coordinate = 1e12;

/// Checks the sections of the MSH file `bytes` whose header is `header` (as
/// parse_msh_header found it), in formats 2.2 and 4.1, ASCII and binary (either byte
/// order), 2D and 3D. Refused, with where ("line 17" in an ASCII file, "byte 1234" in a
/// binary one) and the bound:
/// - a section other than $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements, or
///   one of them twice, or text between sections;
/// - a count (of nodes, elements, entities, blocks, tags) larger than the bytes left in
///   the file can hold (each number takes at least 2 bytes in ASCII, a digit and a
///   separator, and its own size in binary), checked before anything is read by it;
/// - a node or element tag (or a node an element names) below 1, above max_msh_tag or
///   above the section's sparse-tag bound, or (4.1) outside the section's declared
///   minimum and maximum tag, a declared maximum above the sparse-tag bound, and a
///   declared count that the blocks do not add up to;
/// - a coordinate (of a node or an entity's box) that is not finite, is subnormal, or
///   has |x| > max_msh_coordinate;
/// - a node tag given twice;
/// - an element type Gmsh does not number 1…31, a number that is not one, a section
///   that does not end with its `$End` line where its counts say.
/// Returns the first problem as "PATH:LINE: what (the bound)" (ASCII) or "PATH: byte
/// N: ..." (binary), or nothing. Never allocates more than a bit per admissible tag.
std::optional<std::string> msh_data_problem(std::string_view bytes, const MshHeader& header,
                                            std::string_view path);

} // namespace formflow::mesh
