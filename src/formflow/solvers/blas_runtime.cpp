// SPDX-License-Identifier: MIT
// OpenBLAS's own report of its configuration, kernels and threads, when it is loaded.
#include "formflow/solvers/blas_runtime.hpp"

#include <dlfcn.h>

namespace formflow::solvers {

namespace {

/// OpenBLAS's query `name` (char* (void) or int (void)), or null when the process's BLAS
/// is not OpenBLAS.
template <class Function> Function openblas_query(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

} // namespace

BlasRuntime blas_runtime() {
  BlasRuntime runtime;
  using Text = char* (*)();
  using Count = int (*)();
  const Text config = openblas_query<Text>("openblas_get_config");
  if (!config) {
    runtime.library = "not OpenBLAS";
    return runtime;
  }
  runtime.library = config();
  if (const Text core = openblas_query<Text>("openblas_get_corename")) runtime.core = core();
  if (const Count threads = openblas_query<Count>("openblas_get_num_threads"))
    runtime.threads = threads();
  return runtime;
}

} // namespace formflow::solvers
