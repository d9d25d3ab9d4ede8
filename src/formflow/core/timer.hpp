// SPDX-License-Identifier: MIT
// Named phase timers: a scoped timer adds its wall time to a phase total.
#pragma once

#include <chrono>
#include <map>
#include <string>

namespace formflow {

/// Accumulated wall-clock seconds per named phase ("assembly", "factorization", ...),
/// and event counts ("factorization" calls, "krylov iterations", ...) that say what
/// the seconds bought.
class PhaseTimes {
public:
  void add(const std::string& phase, double seconds) { seconds_[phase] += seconds; }
  void count(const std::string& event, long n = 1) { counts_[event] += n; }
  long counted(const std::string& event) const {
    auto it = counts_.find(event);
    return it == counts_.end() ? 0 : it->second;
  }
  double get(const std::string& phase) const {
    auto it = seconds_.find(phase);
    return it == seconds_.end() ? 0.0 : it->second;
  }
  const std::map<std::string, double>& all() const { return seconds_; }
  const std::map<std::string, long>& all_counts() const { return counts_; }

private:
  std::map<std::string, double> seconds_;
  std::map<std::string, long> counts_;
};

/// Adds the time between construction and destruction to `times[phase]` and
/// counts the entry under the phase's name.
class ScopedTimer {
public:
  ScopedTimer(PhaseTimes& times, std::string phase)
      : times_(times), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {
    times_.count(phase_);
  }
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

} // namespace formflow
