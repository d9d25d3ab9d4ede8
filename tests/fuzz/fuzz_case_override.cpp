// SPDX-License-Identifier: MIT
// Fuzz target: each line of the input is one `--set key=value` (split at the first
// '='), applied to the default case in order.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "fuzz/fuzz_support.hpp"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(formflow::fuzz::as_text(data, size));
  std::vector<formflow::io::Override> overrides;
  for (std::string line; std::getline(lines, line);) {
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue; // the CLI refuses these before load_case
    overrides.emplace_back(line.substr(0, equals), line.substr(equals + 1));
  }
  try {
    const formflow::io::Case case_ = formflow::io::load_case("", overrides);
    (void)case_;
  } catch (const formflow::InputError& error) {
    (void)error.what();
  }
  return 0;
}
