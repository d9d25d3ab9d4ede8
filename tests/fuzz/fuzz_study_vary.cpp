// SPDX-License-Identifier: MIT
// Fuzz target: the input as the `--vary key=v1,v2,...` of `formflow study`, planned
// (parsed and every rung's case loaded) on the default case; nothing is solved.
#include "formflow/app/study.hpp"
#include "formflow/core/error.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const formflow::app::StudyPlan plan =
        formflow::app::plan_study("", formflow::fuzz::as_text(data, size), {});
    (void)plan;
  } catch (const formflow::InputError& error) {
    (void)error.what();
  }
  return 0;
}
