// SPDX-License-Identifier: MIT
// Which PETSc options a case file may carry: solver and preconditioner choices, never a
// viewer, a monitor, an options file or anything else that reads or writes a file.
#pragma once

#include "formflow/solvers/petsc_option_text.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace formflow::solvers {

/// Why `option` may not come from a case file (solver.petsc_options), or nothing.
///
/// A case file is data: it may choose solvers and tune them, nothing else. The name,
/// after any number of sub-solver prefixes (`-fieldsplit_<split>_`, `-mg_levels_`,
/// `-mg_levels_<n>_`, `-mg_coarse_`, `-sub_`, `-redundant_`), must be one of
/// - `-ksp_type`, `-ksp_rtol`, `-ksp_atol`, `-ksp_divtol`, `-ksp_max_it`,
///   `-ksp_norm_type`, `-ksp_pc_side`, `-ksp_initial_guess_nonzero`, `-ksp_gmres_*`,
///   `-ksp_chebyshev_*`, `-ksp_richardson_scale`;
/// - `-pc_type`, `-pc_use_amat`, and the preconditioners' parameters `-pc_factor_*`,
///   `-pc_hypre_*`, `-pc_gamg_*`, `-pc_mg_*`, `-pc_fieldsplit_*`, `-pc_asm_*`,
///   `-pc_bjacobi_*`, `-pc_sor_*`, `-pc_jacobi_*`, `-pc_bddc_*`, `-pc_ml_*`;
/// - `-mat_type`, `-mat_partitioning_type`, `-mat_mumps_icntl_<n>` (not 1–3, MUMPS' output
///   units, which write `fort.<n>` files, nor 22, out-of-core files), `-mat_mumps_cntl_<n>`,
///   `-mat_superlu_dist_*`;
/// - `-snes_type`, `-snes_rtol`, `-snes_atol`, `-snes_stol`, `-snes_max_it`,
///   `-snes_linesearch_type`;
/// - formflow's own `-formflow_inexact_steps`, `-formflow_saddle_point_nest`,
///   `-formflow_velocity_node_blocks`;
/// and contain none of `view`, `monitor`, `log`, `draw`, `dump`, `print`, `file`. A value
/// is a number, a word or a comma list (letters, digits, `_ + - . ,`; BoomerAMG's
/// relaxation names such as `symmetric-SOR/Jacobi` too), never a path or a viewer
/// (`ascii:out.txt`), and no `*_type` is `python` (which loads code).
std::optional<std::string> case_petsc_option_refusal(const PetscOption& option);

/// The first refusal among the options of `text` (parse_petsc_options), or nothing.
std::optional<std::string> case_petsc_options_refusal(std::string_view text);

/// What a case file may set, in one line for a hint.
std::string_view case_petsc_options_allowed();

} // namespace formflow::solvers
