// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as a case file. An InputError is the expected answer to bad
// input; anything else escaping load_case (or a crash, leak, hang) is a bug.
#include "formflow/core/error.hpp"
#include "formflow/io/case.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const formflow::io::Case case_ =
        formflow::io::load_case_text(formflow::fuzz::as_text(data, size), "fuzz.toml", {});
    (void)case_;
  } catch (const formflow::InputError& error) {
    (void)error.what();
  }
  return 0;
}
