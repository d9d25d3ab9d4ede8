// SPDX-License-Identifier: MIT
// run_tasks: every task once, on several threads, the first failure rethrown after all.
#include "formflow/core/parallel_tasks.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace formflow {
namespace {

TEST(ParallelTasks, RunsEveryTaskOnce) {
  for (const std::size_t threads : {1u, 2u, 5u}) {
    std::vector<std::atomic<int>> runs(37);
    run_tasks(runs.size(), threads, [&](std::size_t task) { ++runs[task]; });
    for (const auto& count : runs) EXPECT_EQ(count.load(), 1) << threads << " threads";
  }
  run_tasks(0, 3, [](std::size_t) { FAIL() << "no task to run"; });
}

TEST(ParallelTasks, OneThreadIsTheCallersOwn) {
  const std::thread::id caller = std::this_thread::get_id();
  std::set<std::thread::id> seen;
  run_tasks(8, 1, [&](std::size_t) { seen.insert(std::this_thread::get_id()); });
  EXPECT_EQ(seen, std::set<std::thread::id>{caller});
}

TEST(ParallelTasks, AFailureIsRethrownAndNoTaskStartsAfterIt) {
  // One thread: the tasks run in order, so exactly tasks 0 … 3 start.
  int started = 0;
  EXPECT_THROW(run_tasks(100, 1,
                         [&](std::size_t task) {
                           ++started;
                           if (task == 3) throw std::runtime_error("task 3");
                         }),
               std::runtime_error);
  EXPECT_EQ(started, 4);
  // Several threads: the failure comes back to the caller whichever thread met it.
  for (const std::size_t failing : {0u, 1u, 6u})
    EXPECT_THROW(run_tasks(7, 3,
                           [&](std::size_t task) {
                             if (task == failing) throw std::runtime_error("failing task");
                           }),
                 std::runtime_error);
}

TEST(ParallelTasks, OmpNumThreadsCapsTheComputeThreads) {
  const char* old = std::getenv("OMP_NUM_THREADS");
  const std::string saved = old ? old : "";
  setenv("OMP_NUM_THREADS", "1", 1);
  EXPECT_EQ(compute_threads(), 1u);
  setenv("OMP_NUM_THREADS", "not a number", 1); // ignored: the machine's threads
  EXPECT_EQ(compute_threads(), std::max(1u, std::thread::hardware_concurrency()));
  unsetenv("OMP_NUM_THREADS");
  EXPECT_EQ(compute_threads(), std::max(1u, std::thread::hardware_concurrency()));
  if (old) setenv("OMP_NUM_THREADS", saved.c_str(), 1);
}

} // namespace
} // namespace formflow
