// SPDX-License-Identifier: MIT
// GOMP_parallel with the team size capped by the live OpenMpTeamLimit.
#include "formflow/solvers/openmp_team_limit.hpp"

#include <dlfcn.h>

namespace formflow::solvers {

namespace {

/// The innermost live limit of this thread; 0: none (the library's own team size).
thread_local unsigned team_limit_of_this_thread = 0;

using GompParallel = void (*)(void (*)(void*), void*, unsigned, unsigned);

/// libgomp's own GOMP_parallel (the next definition in the lookup order), looked up when
/// the library loads: a dlsym at the first parallel region could wait for the loader's
/// lock behind a module loaded on another thread (see blas_thread_limit.cpp).
const GompParallel libgomp_parallel =
    reinterpret_cast<GompParallel>(dlsym(RTLD_NEXT, "GOMP_parallel"));

} // namespace

OpenMpTeamLimit::OpenMpTeamLimit(unsigned threads) : previous_(team_limit_of_this_thread) {
  team_limit_of_this_thread = threads;
}

OpenMpTeamLimit::~OpenMpTeamLimit() {
  team_limit_of_this_thread = previous_;
}

} // namespace formflow::solvers

/// libgomp's ABI for `#pragma omp parallel` (GCC ≥ 4.9): run `function(data)` on a team
/// of `threads` (0: the default size). Forwarded to the next definition in the
/// lookup order, libgomp's. Default visibility: the library is built with hidden symbols,
/// and a hidden definition could not interpose on CHOLMOD's reference.
extern "C" __attribute__((visibility("default"))) void
GOMP_parallel(void (*function)(void*), void* data, unsigned threads, unsigned flags) {
  using formflow::solvers::libgomp_parallel;
  const unsigned limit = formflow::solvers::team_limit_of_this_thread;
  if (limit != 0 && (threads == 0 || threads > limit)) threads = limit;
  if (libgomp_parallel) {
    libgomp_parallel(function, data, threads, flags);
    return;
  }
  // Not reached while a caller is linked against libgomp (it is then loaded and next
  // in the order); without it, the region runs on this thread, as a team of one.
  function(data);
}
