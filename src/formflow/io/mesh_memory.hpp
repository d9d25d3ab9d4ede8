// SPDX-License-Identifier: MIT
// Refusing, at validation time, a mesh that cannot fit in this machine's memory.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/io/case_keys.hpp"

#include <optional>
#include <string_view>

namespace formflow::io {

/// Bytes a run needs per velocity dof, at least. Measured peak memory (VmHWM)
/// of whole runs: Q2 145 MiB at 77 762 dofs and 571 MiB at 309 122
/// (docs/benchmarks.md: 1.93 kB per dof between the two), Q1 553 MiB at
/// 309 122 dofs (1.88 kB per dof; command in docs/benchmarks.md). The
/// Cholesky factor fills in faster than linearly (n log n in 2D under nested
/// dissection), and Newton's tangent needs more than the secant's matrix, so
/// larger runs need more per dof: the estimate is a lower bound, and a mesh is
/// refused only when even that bound does not fit.
inline constexpr Real run_bytes_per_dof = 1800.0;

/// Machine memory assumed when /proc/meminfo cannot be read.
inline constexpr Real fallback_memory_bytes = 64.0 * 1024 * 1024 * 1024;

/// The mesh a case asks for, counted before it is built.
struct MeshMemoryEstimate {
  Real cells = 0.0; ///< exact for the structured grid; Gmsh's mesh has about as many
  Real dofs = 0.0;  ///< velocity dofs, dim·order^dim·cells (interior nodes; a slight undercount)
  Real bytes = 0.0; ///< run_bytes_per_dof · dofs
};

/// The estimate for `case_` with mesh.size = `size`; std::nullopt for a mesh
/// read from a file, which is known only once read.
std::optional<MeshMemoryEstimate> estimate_mesh_memory(const Case& case_, Real size);

/// MemTotal from `meminfo` (the text of /proc/meminfo) in bytes.
std::optional<Real> parse_mem_total(std::string_view meminfo);

/// This machine's MemTotal in bytes (read once per process), or fallback_memory_bytes.
Real machine_memory_bytes();

/// Why the case's mesh cannot run in `memory_bytes`: the cell count, the
/// estimate and the memory in the message, a valid mesh.size that fits in the
/// hint; std::nullopt when it fits.
std::optional<KeyProblem> mesh_memory_problem(const Case& case_, Real memory_bytes);

} // namespace formflow::io
