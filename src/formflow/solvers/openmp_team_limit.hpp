// SPDX-License-Identifier: MIT
// A cap on the OpenMP teams that libraries open from this thread.
#pragma once

namespace formflow::solvers {

/// While alive, every OpenMP parallel region opened from the constructing thread
/// runs with at most `threads` threads, whatever team size the library compiled in.
///
/// Why: CHOLMOD 3 (Debian's SuiteSparse 5) opens a team of four threads, its
/// compiled CHOLMOD_OMP_NUM_THREADS, which neither OMP_NUM_THREADS nor
/// omp_set_num_threads lowers, around the loops that clear and fill each supernode:
/// memory traffic, a futex wake-up of the whole team per supernode, on two cores
/// twice oversubscribed. On the adaptive sticking ram (cases/adaptive-sticking-ram.toml,
/// one BLAS thread) that was 52.7 s against 31.3 s with one thread
/// (docs/benchmarks.md "CHOLMOD's OpenMP teams"). The dense work inside a supernode is
/// BLAS, threaded by OpenBLAS's own pool, which this does not touch.
///
/// A region of one thread (capped so, or one by the library's `if` clause) runs on this
/// thread without a libgomp team: libgomp ends even a one-thread region with a futex
/// wake-up of its (absent) team, a system call per region (1.33 M on the adaptive
/// sticking ram, 8.25 → 6.19 s end to end without them; docs/benchmarks.md "One-thread
/// OpenMP regions").
///
/// How: libgomp's entry point for a parallel region, GOMP_parallel, is defined in
/// this library (default visibility) and forwards to libgomp's with the team size
/// capped. The linker exports it from an executable that links this library, since
/// CHOLMOD refers to it, and the dynamic linker binds CHOLMOD's call to the
/// executable's definition ahead of libgomp's. Regions opened while no limit is alive
/// pass unchanged. The Python module, whose static library's symbols stay local, links
/// this file's object directly so that it exports the entry point too
/// (python/CMakeLists.txt).
class OpenMpTeamLimit {
public:
  explicit OpenMpTeamLimit(unsigned threads);
  ~OpenMpTeamLimit();
  OpenMpTeamLimit(const OpenMpTeamLimit&) = delete;
  OpenMpTeamLimit& operator=(const OpenMpTeamLimit&) = delete;

private:
  unsigned previous_;
};

} // namespace formflow::solvers
