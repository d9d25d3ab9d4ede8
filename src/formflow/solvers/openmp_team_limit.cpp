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

/// libgomp's omp_get_level: the regions enclosing this thread (0: none), looked up so.
using OmpLevel = int (*)();
const OmpLevel libgomp_level = reinterpret_cast<OmpLevel>(dlsym(RTLD_NEXT, "omp_get_level"));

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
  using formflow::solvers::libgomp_level;
  using formflow::solvers::libgomp_parallel;
  const unsigned limit = formflow::solvers::team_limit_of_this_thread;
  if (limit != 0 && (threads == 0 || threads > limit)) threads = limit;
  // A team of one outside any region runs on this thread without libgomp's team:
  // libgomp ends even a one-thread region by waking the rest of its team with a futex
  // system call, and CHOLMOD opens a region per supernode (capped to one thread here, or
  // one by its `if` clause): 1.33 M such calls on the adaptive sticking ram, about 0.8 s
  // of its main thread. Without a team the region's worksharing, barriers and omp_get_*
  // see the implicit team of one that OpenMP defines outside a parallel region. Inside
  // a region they would see the enclosing team instead, so a nested region keeps
  // libgomp's own team. Without libgomp (a caller linked against it loads it, next in
  // the order) every region runs on this thread.
  if (!libgomp_parallel || (threads == 1 && libgomp_level && libgomp_level() == 0)) {
    function(data);
    return;
  }
  libgomp_parallel(function, data, threads, flags);
}
