// SPDX-License-Identifier: MIT
// Named phase timers: a scoped timer adds its wall time to a phase total.
#pragma once

#include <chrono>
#include <map>
#include <string>

namespace formflow {

/// Accumulated wall-clock seconds per named phase ("assembly", "factorization", ...).
class PhaseTimes {
 public:
  void add(const std::string& phase, double seconds) { seconds_[phase] += seconds; }
  double get(const std::string& phase) const {
    auto it = seconds_.find(phase);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  const std::map<std::string, double>& all() const { return seconds_; }

 private:
  std::map<std::string, double> seconds_;
};

/// Adds the time between construction and destruction to `times[phase]`.
class ScopedTimer {
 public:
  ScopedTimer(PhaseTimes& times, std::string phase)
      : times_(times), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { times_.add(phase_, elapsed()); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  PhaseTimes& times_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace formflow
