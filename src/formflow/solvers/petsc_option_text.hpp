// SPDX-License-Identifier: MIT
// The text of solver.petsc_options (and of PETSc options on the command line) as
// name/value pairs, checked without PETSc so that every build validates it.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace formflow::solvers {

/// One entry of the PETSc options database: `-name [value]`.
struct PetscOption {
  std::string name;  ///< with its leading '-', e.g. "-ksp_type"
  std::string value; ///< empty for a flag such as -ksp_monitor
};

/// The options of `text`, whitespace-separated in PETSc's own syntax ("-ksp_type cg
/// -pc_type gamg -ksp_monitor"): a token that starts with '-' followed by a letter
/// is a name, the token after it (if it is not a name) its value. Numbers such as
/// "-1e-3" are values. Throws nothing; a malformed text is reported by
/// petsc_option_syntax_error.
std::vector<PetscOption> parse_petsc_options(std::string_view text);

/// What is wrong with `text` as a list of PETSc options, or nothing: a value with
/// no name before it, a name with characters PETSc names never have, a quote
/// (PETSc's parser would take it literally).
std::optional<std::string> petsc_option_syntax_error(std::string_view text);

/// The arguments of a command line that are PETSc's (`-ksp_*`, `-pc_*`, `-mat_*`,
/// `-fieldsplit_*`, `-mg_*`, `-log_view`, `-options_left`, ... each with the token after
/// it when that is not an option), and the rest, in order. A PETSc flag with no value
/// is best put after the case path, since the token after it is taken as its value
/// unless it starts with '-'.
struct SplitCommandLine {
  std::vector<std::string> petsc;
  std::vector<std::string> rest;
};
SplitCommandLine split_petsc_arguments(std::span<const std::string> arguments);

/// Whether `name` (with its '-') is one of the PETSc option families passed through.
bool is_petsc_option_name(std::string_view name);

} // namespace formflow::solvers
