// SPDX-License-Identifier: MIT
// OMP_NUM_THREADS set for a scope: formflow's own loops (compute_threads()) read it at
// each parallel loop, so a test can compare one thread with several in one process.
#pragma once

#include <cstdlib>
#include <string>

namespace formflow::testing {

/// Sets OMP_NUM_THREADS (compute_threads()'s cap) while alive; restores the value it
/// had, or unsets it if it had none.
class ThreadCap {
public:
  explicit ThreadCap(const std::string& value) {
    if (const char* old = std::getenv("OMP_NUM_THREADS")) old_ = old, had_ = true;
    setenv("OMP_NUM_THREADS", value.c_str(), 1);
  }
  ~ThreadCap() {
    if (had_)
      setenv("OMP_NUM_THREADS", old_.c_str(), 1);
    else
      unsetenv("OMP_NUM_THREADS");
  }
  ThreadCap(const ThreadCap&) = delete;
  ThreadCap& operator=(const ThreadCap&) = delete;

private:
  std::string old_;
  bool had_ = false;
};

} // namespace formflow::testing
