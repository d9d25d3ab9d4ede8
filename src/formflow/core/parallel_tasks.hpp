// SPDX-License-Identifier: MIT
// Independent tasks on a few threads: the calling one and helpers, the first failure rethrown.
#pragma once

#include <cstddef>
#include <functional>

namespace formflow {

/// The threads formflow's own parallel loops use: the machine's hardware threads, or
/// fewer when OMP_NUM_THREADS (the usual cap of a process's compute threads, which
/// CHOLMOD's OpenMP and OpenBLAS also read) is set to a positive count. At least 1.
std::size_t compute_threads();

/// Starts run_tasks's helper threads now rather than at its first call. A thread
/// started while another thread loads a library waits for the loader's lock until that
/// load ends: call this before such a load runs in the background
/// (mesh::preload_gmsh_meshers), so that the loops running meanwhile are not held up.
void start_task_helpers();

/// Runs task(0) … task(n_tasks − 1), each once, on the calling thread and up to
/// `threads` − 1 helper threads (claimed in order from a shared counter: an uneven
/// task does not idle the others). Returns when every task has run; if any threw, the
/// first exception caught is rethrown then, after every thread has stopped (no task is
/// started after a failure). Tasks must not write to the same memory. The helpers are
/// the process's (started once, hardware threads − 1 of them); a call made while they
/// serve another call (from a task, or from another thread) runs its tasks alone.
void run_tasks(std::size_t n_tasks, std::size_t threads,
               const std::function<void(std::size_t task)>& task);

} // namespace formflow
