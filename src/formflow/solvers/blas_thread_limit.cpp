// SPDX-License-Identifier: MIT
// A cap on OpenBLAS's threads around work that its threads do not speed up.
#include "formflow/solvers/blas_thread_limit.hpp"

#include <dlfcn.h>

#include <cstdlib>

namespace formflow::solvers {

namespace {

using GetThreads = int (*)();
using SetThreads = void (*)(int);

/// OpenBLAS's thread-count functions, null when the process's BLAS is not OpenBLAS
/// (looked up, not linked: the alternatives system may serve another BLAS).
struct OpenBlasThreads {
  GetThreads get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  SetThreads set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  /// The user's own choice of the count, which OpenBLAS read at start: kept.
  bool chosen_by_user = std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS") ||
                        std::getenv("OMP_NUM_THREADS");
  bool adjustable() const { return get && set && !chosen_by_user; }
};

const OpenBlasThreads& openblas_threads() {
  static const OpenBlasThreads functions;
  return functions;
}

/// Looked up when the library loads, not at the first factorisation: dlsym waits for
/// the dynamic loader's lock, which Gmsh's module, loaded on another thread while the
/// first cycle solves (mesh::preload_gmsh_meshers), holds for its 0.35 s of
/// relocations; the first factorisation of an adaptive run sat that long in dlsym.
[[maybe_unused]] const OpenBlasThreads& looked_up_at_load = openblas_threads();

} // namespace

BlasThreadLimit::BlasThreadLimit(int threads) {
  const OpenBlasThreads& openblas = openblas_threads();
  if (threads <= 0 || !openblas.adjustable()) return;
  const int current = openblas.get();
  if (current <= threads) return;
  openblas.set(threads);
  restore_ = current;
}

BlasThreadLimit::~BlasThreadLimit() {
  if (restore_ > 0) openblas_threads().set(restore_);
}

} // namespace formflow::solvers
