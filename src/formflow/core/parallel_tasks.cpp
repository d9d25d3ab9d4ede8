// SPDX-License-Identifier: MIT
// run_tasks: an atomic task counter shared by the caller and helper threads that live
// for the process (a thread's start costs about 34 µs, and one started while another
// thread loads a library waits for that load: see start_task_helpers).
#include "formflow/core/parallel_tasks.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace formflow {

namespace {

/// The machine's hardware threads, read once (glibc reads them from /sys at each call).
std::size_t hardware_threads() {
  static const std::size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  return hardware;
}

/// hardware_threads() − 1 helper threads waiting for work. One run at a time: `run`
/// returns false when the helpers are taken (a run_tasks on another thread, or inside
/// a task), and the caller then does the work alone. Never destroyed: the helpers wait
/// on their condition at exit and end with the process, so no exit path has to join
/// them (a destructor's join would hang an exit that left a run unfinished).
class TaskHelpers {
public:
  TaskHelpers() {
    const std::size_t count = hardware_threads() - 1;
    for (std::size_t k = 0; k < count; ++k) std::thread([this, k] { serve(k); }).detach();
    size_ = count;
  }

  std::size_t size() const { return size_; }

  /// work() on `helpers` (≤ size()) of the helpers and on the calling thread; returns once
  /// all have returned from it. False, with nothing run, when another run holds them.
  bool run(std::size_t helpers, const std::function<void()>& work) {
    bool expected = false;
    if (!busy_.compare_exchange_strong(expected, true)) return false;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      work_ = &work;
      wanted_ = helpers;
      pending_ = helpers;
      ++generation_;
    }
    wake_.notify_all();
    work(); // the caller's own share
    {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [this] { return pending_ == 0; });
      work_ = nullptr;
    }
    busy_ = false;
    return true;
  }

private:
  void serve(std::size_t id) {
    std::size_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      wake_.wait(lock, [&] { return generation_ != seen; });
      seen = generation_;
      if (id >= wanted_) continue;
      const std::function<void()>* work = work_;
      lock.unlock();
      (*work)(); // run_tasks's work catches every task's exception
      lock.lock();
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void()>* work_ = nullptr;
  std::size_t wanted_ = 0, pending_ = 0, generation_ = 0, size_ = 0;
  std::atomic<bool> busy_{false};
};

TaskHelpers& task_helpers() {
  static TaskHelpers* helpers = new TaskHelpers; // never deleted: see TaskHelpers
  return *helpers;
}

} // namespace

std::size_t compute_threads() {
  std::size_t threads = hardware_threads();
  if (const char* text = std::getenv("OMP_NUM_THREADS")) {
    // OpenMP's syntax allows a list ("4,2": nested levels); the first level is the cap.
    std::size_t cap = 0;
    const char* end = text + std::strlen(text);
    const auto [rest, error] = std::from_chars(text, end, cap);
    if (error == std::errc() && rest != text && cap > 0) threads = std::min(threads, cap);
  }
  return threads;
}

void start_task_helpers() {
  task_helpers();
}

void run_tasks(std::size_t n_tasks, std::size_t threads,
               const std::function<void(std::size_t task)>& task) {
  std::atomic<std::size_t> next{0};
  std::mutex failure_lock;
  std::exception_ptr failure;
  const std::function<void()> work = [&] {
    for (std::size_t k = next++; k < n_tasks; k = next++) {
      try {
        task(k);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_lock);
        if (!failure) failure = std::current_exception();
        next = n_tasks; // no thread starts another task
      }
    }
  };
  const std::size_t used = std::min(std::max<std::size_t>(threads, 1), n_tasks);
  if (used <= 1 || !task_helpers().run(std::min(used - 1, task_helpers().size()), work)) work();
  if (failure) std::rethrow_exception(failure);
}

} // namespace formflow
