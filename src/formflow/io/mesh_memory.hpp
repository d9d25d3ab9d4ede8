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

/// Three dimensions: the Cholesky factor dominates (docs/benchmarks.md, 3D table:
/// 678 MiB at 48 825 dofs, where run_bytes_per_dof accounts for 84 MiB). Under
/// nested dissection a 3D mesh's factor has ~ n^(4/3) entries (the top separator
/// of ~ n^(2/3) dofs is a dense triangle): nnz(L) ≈ c · n^(4/3). c is fitted to
/// CHOLMOD's own counts (summary.json linear_algebra.factor_nonzeros, which do
/// not depend on the machine or its load; docs/3d.md "The memory check"): c grows
/// with n before the asymptote (Q2 round rod: 5.0, 9.8, 13.4 at 1.2 k, 7 k, 49 k
/// dofs; Q1: 13.3 at 48 k), and c = 13, the largest counts' value rounded down, is
/// below the factor of every larger mesh: a lower bound where refusals happen.
/// Each entry is one double, 8 bytes, also a lower bound (supernodal padding, the
/// index arrays and Newton's second factor come on top).
inline constexpr Real solid_factor_coefficient = 13.0;

/// Machine memory assumed when /proc/meminfo cannot be read.
inline constexpr Real fallback_memory_bytes = 64.0 * 1024 * 1024 * 1024;

/// The mesh a case asks for, counted before it is built.
struct MeshMemoryEstimate {
  Real cells = 0.0; ///< exact for the structured grid; Gmsh's mesh has about as many
  Real dofs = 0.0;  ///< velocity dofs, dim·order^dim·cells (interior nodes; a slight undercount)
  /// run_bytes_per_dof · dofs, plus in 3D 8 bytes per estimated factor entry
  Real bytes = 0.0;
  Real factor_entries = 0.0; ///< 3D: the estimated nnz(L); 0 in 2D (inside the per-dof bound)
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
