// SPDX-License-Identifier: MIT
// run_tasks: every task once, on several threads, the first failure rethrown after all;
// the helpers are the process's, and a call while they are taken runs alone.
#include "formflow/core/parallel_tasks.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
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

TEST(ParallelTasks, TheHelpersAreTheProcesssNotOnePerCall) {
  // Over many calls, the threads that ran tasks are the caller and at most
  // hardware − 1 helpers: the same ones each time, none started per call.
  start_task_helpers();
  std::mutex lock;
  std::set<std::thread::id> seen;
  for (int call = 0; call < 50; ++call)
    run_tasks(16, 8, [&](std::size_t) {
      std::this_thread::sleep_for(std::chrono::microseconds(50));
      const std::lock_guard<std::mutex> guard(lock);
      seen.insert(std::this_thread::get_id());
    });
  EXPECT_LE(seen.size(), std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(seen.count(std::this_thread::get_id()), 1u);
}

TEST(ParallelTasks, ACallInsideATaskOrBesideAnotherRunsItsTasksToo) {
  // Inside a task the helpers are taken: the inner call runs alone, and returns.
  std::vector<std::atomic<int>> inner(8 * 13);
  run_tasks(8, 4, [&](std::size_t outer) {
    run_tasks(13, 4, [&](std::size_t task) { ++inner[outer * 13 + task]; });
  });
  for (const auto& count : inner) EXPECT_EQ(count.load(), 1);
  // Two threads calling at once: each call runs every one of its tasks once.
  std::vector<std::atomic<int>> first(200), second(200);
  std::thread other([&] {
    for (int repeat = 0; repeat < 20; ++repeat)
      run_tasks(10, 2, [&](std::size_t task) { ++second[repeat * 10 + task]; });
  });
  for (int repeat = 0; repeat < 20; ++repeat)
    run_tasks(10, 2, [&](std::size_t task) { ++first[repeat * 10 + task]; });
  other.join();
  for (const auto& count : first) EXPECT_EQ(count.load(), 1);
  for (const auto& count : second) EXPECT_EQ(count.load(), 1);
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
