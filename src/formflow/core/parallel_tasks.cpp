// SPDX-License-Identifier: MIT
// run_tasks: an atomic task counter shared by the caller and std::async helpers.
#include "formflow/core/parallel_tasks.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

namespace formflow {

std::size_t compute_threads() {
  // The machine's count once (glibc reads it from /sys at each call); the cap each time.
  static const std::size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  std::size_t threads = hardware;
  if (const char* text = std::getenv("OMP_NUM_THREADS")) {
    // OpenMP's syntax allows a list ("4,2": nested levels); the first level is the cap.
    std::size_t cap = 0;
    const char* end = text + std::strlen(text);
    const auto [rest, error] = std::from_chars(text, end, cap);
    if (error == std::errc() && rest != text && cap > 0) threads = std::min(threads, cap);
  }
  return threads;
}

void run_tasks(std::size_t n_tasks, std::size_t threads,
               const std::function<void(std::size_t task)>& task) {
  std::atomic<std::size_t> next{0};
  std::mutex failure_lock;
  std::exception_ptr failure;
  const auto work = [&] {
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
  std::vector<std::future<void>> helpers;
  for (std::size_t k = 1; k < used; ++k) helpers.push_back(std::async(std::launch::async, work));
  work();
  for (std::future<void>& helper : helpers) helper.wait();
  if (failure) std::rethrow_exception(failure);
}

} // namespace formflow
