// SPDX-License-Identifier: MIT
// The vetted list of PETSc options a case file may carry (solver.petsc_options).
#include "formflow/solvers/petsc_case_options.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>

namespace formflow::solvers {

namespace {

bool starts_with(std::string_view text, std::string_view start) {
  return text.substr(0, start.size()) == start;
}

bool ends_with(std::string_view text, std::string_view end) {
  return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

bool all_digits(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

/// Strips one sub-solver prefix from `name` (without its '-'); false if none is there.
bool strip_sub_solver_prefix(std::string_view& name) {
  for (const std::string_view plain : {"mg_coarse_", "sub_", "redundant_"})
    if (starts_with(name, plain)) {
      name.remove_prefix(plain.size());
      return true;
    }
  if (starts_with(name, "mg_levels_")) {
    name.remove_prefix(std::string_view("mg_levels_").size());
    const std::size_t end = name.find('_');
    if (end != std::string_view::npos && all_digits(name.substr(0, end)))
      name.remove_prefix(end + 1);
    return true;
  }
  if (starts_with(name, "fieldsplit_")) {
    const std::string_view split = name.substr(std::string_view("fieldsplit_").size());
    const std::size_t end = split.find('_');
    // A split's name, then its options: "fieldsplit_u_pc_type", never "fieldsplit_type".
    if (end == 0 || end == std::string_view::npos) return false;
    name = split.substr(end + 1);
    return true;
  }
  return false;
}

constexpr std::array<std::string_view, 21> exact_names = {
    "ksp_type",
    "ksp_rtol",
    "ksp_atol",
    "ksp_divtol",
    "ksp_max_it",
    "ksp_norm_type",
    "ksp_pc_side",
    "ksp_initial_guess_nonzero",
    "ksp_richardson_scale",
    "pc_type",
    "pc_use_amat",
    "mat_type",
    "mat_partitioning_type",
    "snes_type",
    "snes_rtol",
    "snes_atol",
    "snes_stol",
    "snes_max_it",
    "snes_linesearch_type",
    "formflow_inexact_steps",
    "formflow_saddle_point_nest",
};

constexpr std::array<std::string_view, 15> families = {
    "ksp_gmres_", "ksp_chebyshev_", "pc_factor_", "pc_hypre_",       "pc_gamg_",
    "pc_mg_",     "pc_fieldsplit_", "pc_asm_",    "pc_bjacobi_",     "pc_sor_",
    "pc_jacobi_", "pc_bddc_",       "pc_ml_",     "mat_mumps_cntl_", "mat_superlu_dist_",
};

/// Words that name output, input or a viewer wherever they stand in a name.
constexpr std::array<std::string_view, 7> output_words = {"view", "monitor", "log", "draw",
                                                          "dump", "print",   "file"};

/// MUMPS' ICNTL(1..3) are Fortran output units (a unit not open writes `fort.<n>`) and
/// ICNTL(22) puts the factors out of core, into files.
bool is_allowed_mumps_control(std::string_view number) {
  return all_digits(number) && number != "1" && number != "2" && number != "3" && number != "22" &&
         number.size() <= 2;
}

bool is_listed(std::string_view base) {
  if (base == "formflow_velocity_node_blocks") return true;
  for (const std::string_view exact : exact_names)
    if (base == exact) return true;
  if (starts_with(base, "mat_mumps_icntl_"))
    return is_allowed_mumps_control(base.substr(std::string_view("mat_mumps_icntl_").size()));
  for (const std::string_view family : families)
    if (starts_with(base, family) && base.size() > family.size()) return true;
  return false;
}

bool is_value_character(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '+' || c == '-' ||
         c == '.' || c == ',';
}

/// BoomerAMG's relaxation names with a '/', which PETSc takes from a fixed list.
bool is_relaxation_name(std::string_view base, std::string_view value) {
  if (!starts_with(base, "pc_hypre_boomeramg_relax_type_")) return false;
  for (const std::string_view name :
       {"SOR/Jacobi", "backward-SOR/Jacobi", "symmetric-SOR/Jacobi", "l1scaled-SOR/Jacobi"})
    if (value == name) return true;
  return false;
}

} // namespace

std::optional<std::string> case_petsc_option_refusal(const PetscOption& option) {
  std::string_view name = option.name;
  if (!name.empty() && name.front() == '-') name.remove_prefix(1);
  for (const std::string_view word : output_words)
    if (name.find(word) != std::string_view::npos)
      return fmt::format("{} reads or writes outside the solve ('{}': a viewer, monitor, log or "
                         "file); a case file is data and may not",
                         option.name, word);
  std::string_view base = name;
  while (strip_sub_solver_prefix(base)) {
  }
  if (!is_listed(base))
    return fmt::format("{} is not one of the solver options a case file may set", option.name);
  for (const char c : option.value)
    if (!is_value_character(c) && !is_relaxation_name(base, option.value))
      return fmt::format("{} {}: a value is a number, a word or a comma list, never a path or a "
                         "viewer such as ascii:FILE",
                         option.name, option.value);
  if (ends_with(base, "_type") && option.value == "python")
    return fmt::format("{} python loads Python code; a case file may not", option.name);
  return std::nullopt;
}

std::optional<std::string> case_petsc_options_refusal(std::string_view text) {
  for (const PetscOption& option : parse_petsc_options(text))
    if (auto refusal = case_petsc_option_refusal(option)) return refusal;
  return std::nullopt;
}

std::string_view case_petsc_options_allowed() {
  return "a case may set solver types, tolerances and preconditioner parameters (-ksp_type, "
         "-ksp_rtol, -ksp_max_it, -pc_type, -pc_factor_*, -pc_hypre_*, -pc_gamg_*, -pc_mg_*, "
         "-pc_fieldsplit_*, -mat_mumps_icntl_*, behind -fieldsplit_<split>_, -mg_levels_, "
         "-mg_coarse_, -sub_); viewers, monitors, -options_file and -help only on the command "
         "line (docs/petsc.md)";
}

} // namespace formflow::solvers
