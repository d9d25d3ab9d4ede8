// SPDX-License-Identifier: MIT
// PETSc option text: tokenising and the syntax check of solver.petsc_options.
#include "formflow/solvers/petsc_option_text.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>

namespace formflow::solvers {

namespace {

std::vector<std::string_view> tokens(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t at = 0;
  while (at < text.size()) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    const std::size_t begin = at;
    while (at < text.size() && !std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    if (at > begin) out.push_back(text.substr(begin, at - begin));
  }
  return out;
}

/// "-name": a dash and a letter (so "-1e-3" and "-" are values, not names).
bool is_name(std::string_view token) {
  return token.size() >= 2 && token[0] == '-' && std::isalpha(static_cast<unsigned char>(token[1]));
}

bool is_name_character(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

} // namespace

std::vector<PetscOption> parse_petsc_options(std::string_view text) {
  std::vector<PetscOption> options;
  for (const std::string_view token : tokens(text)) {
    if (is_name(token))
      options.push_back({std::string(token), {}});
    else if (!options.empty() && options.back().value.empty())
      options.back().value = token;
  }
  return options;
}

std::optional<std::string> petsc_option_syntax_error(std::string_view text) {
  bool value_allowed = false;
  for (const std::string_view token : tokens(text)) {
    if (token.find_first_of("\"'") != std::string_view::npos)
      return fmt::format("`{}`: PETSc takes quotes literally; write values unquoted", token);
    if (is_name(token)) {
      for (const char c : token.substr(1))
        if (!is_name_character(c))
          return fmt::format("`{}`: an option name has letters, digits and '_' only after its '-'",
                             token);
      value_allowed = true;
      continue;
    }
    if (!value_allowed)
      return fmt::format("`{}` is not an option name (these start with '-') and follows no "
                         "option that takes it as its value",
                         token);
    value_allowed = false;
  }
  return std::nullopt;
}

bool is_petsc_option_name(std::string_view name) {
  static constexpr std::array<std::string_view, 13> families = {
      "-ksp_", "-pc_",  "-mat_",         "-fieldsplit_", "-mg_",   "-sub_",   "-vec_",
      "-log_", "-info", "-options_left", "-malloc_",     "-snes_", "-memory_"};
  for (const std::string_view family : families)
    if (name.substr(0, family.size()) == family) return true;
  return false;
}

SplitCommandLine split_petsc_arguments(std::span<const std::string> arguments) {
  SplitCommandLine split;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    if (!is_petsc_option_name(arguments[i])) {
      split.rest.push_back(arguments[i]);
      continue;
    }
    split.petsc.push_back(arguments[i]);
    if (i + 1 < arguments.size() && !is_name(arguments[i + 1]))
      split.petsc.push_back(arguments[++i]);
  }
  return split;
}

} // namespace formflow::solvers
