// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as solver.petsc_options, through the syntax check and the
// filter of what a case file may carry (solvers/petsc_case_options.hpp).
#include "formflow/solvers/petsc_case_options.hpp"
#include "formflow/solvers/petsc_option_text.hpp"
#include "fuzz/fuzz_support.hpp"

#include <cstdlib>
#include <string_view>

namespace {

bool contains(std::string_view text, std::string_view part) {
  return text.find(part) != std::string_view::npos;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = formflow::fuzz::as_text(data, size);
  if (formflow::solvers::petsc_option_syntax_error(text)) return 0;
  const auto refusal = formflow::solvers::case_petsc_options_refusal(text);
  if (refusal && refusal->empty()) std::abort(); // a refusal always says why
  if (refusal) return 0;
  // Accepted: nothing that reads or writes a file, nothing but solver choices.
  for (const auto& option : formflow::solvers::parse_petsc_options(text)) {
    for (const std::string_view word :
         {"view", "monitor", "log", "dump", "options", "help", "prefix", "file", "python"})
      if (contains(option.name, word) || (word == "python" && option.value == word)) std::abort();
    if (contains(option.value, ":") || contains(option.value, "~") || contains(option.value, "\\"))
      std::abort();
    if (contains(option.value, "/") && !contains(option.name, "_relax_type_")) std::abort();
  }
  return 0;
}
