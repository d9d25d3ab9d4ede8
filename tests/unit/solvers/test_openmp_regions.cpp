// SPDX-License-Identifier: MIT
// OpenMP regions through formflow's GOMP_parallel (solvers/openmp_team_limit.hpp): a
// region capped to one thread runs on the calling thread without a libgomp team (whose
// end costs a futex system call per region), and a wider one still gets its team.
#include "formflow/solvers/openmp_team_limit.hpp"

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>

// libgomp's entry point for `#pragma omp parallel`, defined by formflow's library.
extern "C" void GOMP_parallel(void (*function)(void*), void* data, unsigned threads,
                              unsigned flags);

namespace formflow::testing {
namespace {

/// What the region's body saw, on every thread that ran it.
struct RegionRecord {
  std::mutex mutex;
  std::set<std::thread::id> threads;
  std::atomic<int> calls{0};
  std::atomic<int> deepest_level{-1};
};

/// A libgomp query (omp_get_level, omp_get_thread_num, …), found in the process
/// (CHOLMOD links libgomp); −1 if it is not there. omp_get_level: 0 outside any team,
/// 1 inside a region's team.
int openmp_call(const char* name) {
  using Query = int (*)();
  const auto query = reinterpret_cast<Query>(dlsym(RTLD_DEFAULT, name));
  return query ? query() : -1;
}

void record_region(void* data) {
  auto& record = *static_cast<RegionRecord*>(data);
  ++record.calls;
  const int level = openmp_call("omp_get_level");
  int seen = record.deepest_level.load();
  while (level > seen && !record.deepest_level.compare_exchange_weak(seen, level)) {
  }
  const std::lock_guard lock(record.mutex);
  record.threads.insert(std::this_thread::get_id());
}

// A suite of its own: ctest runs it in its own process, whose libgomp pool the wider
// region below starts.
TEST(OpenMpRegions, ACappedRegionRunsHereWithoutATeam) {
  ASSERT_NE(openmp_call("omp_get_level"), -1) << "libgomp is not in the process";
  RegionRecord record;
  {
    const solvers::OpenMpTeamLimit one(1);
    GOMP_parallel(record_region, &record, 0, 0); // 0: the library's default team size
  }
  EXPECT_EQ(record.calls.load(), 1);
  EXPECT_EQ(record.threads, std::set<std::thread::id>{std::this_thread::get_id()});
  EXPECT_EQ(record.deepest_level.load(), 0) << "a libgomp team was made for one thread";
}

TEST(OpenMpRegions, AOneThreadRegionWithoutACapRunsHereToo) {
  // CHOLMOD's `if` clauses pass one thread when a loop is short.
  RegionRecord record;
  GOMP_parallel(record_region, &record, 1, 0);
  EXPECT_EQ(record.calls.load(), 1);
  EXPECT_EQ(record.deepest_level.load(), 0);
}

/// What a one-thread region nested in a two-thread one saw, per outer thread.
struct NestedRecord {
  std::atomic<int> inner_calls{0};
  std::atomic<int> wrong_numbering{0}; ///< inner regions that did not see a team of one
};

void inner_region(void* data) {
  auto& record = *static_cast<NestedRecord*>(data);
  ++record.inner_calls;
  // Its own team of one: thread 0 of 1, two levels deep. Run without a team it would
  // see the outer team (thread 0 or 1 of 2) and split a loop's static schedule with it.
  if (openmp_call("omp_get_thread_num") != 0 || openmp_call("omp_get_num_threads") != 1 ||
      openmp_call("omp_get_level") != 2)
    ++record.wrong_numbering;
}

void outer_region(void* data) {
  GOMP_parallel(inner_region, data, 1, 0);
}

TEST(OpenMpRegions, AOneThreadRegionInsideATeamKeepsATeamOfItsOwn) {
  NestedRecord record;
  GOMP_parallel(outer_region, &record, 2, 0);
  EXPECT_EQ(record.inner_calls.load(), 2);
  EXPECT_EQ(record.wrong_numbering.load(), 0);
}

TEST(OpenMpRegions, AWiderRegionStillGetsItsTeam) {
  RegionRecord record;
  {
    const solvers::OpenMpTeamLimit two(2);
    GOMP_parallel(record_region, &record, 4, 0);
  }
  EXPECT_EQ(record.calls.load(), 2);
  EXPECT_EQ(record.threads.size(), 2u);
  EXPECT_EQ(record.deepest_level.load(), 1);
}

} // namespace
} // namespace formflow::testing
