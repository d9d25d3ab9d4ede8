// SPDX-License-Identifier: MIT
// The iteration monitor: a header, then one fixed-width line per iteration.
#pragma once

#include "formflow/solvers/stop_reason.hpp"

#include <cstdio>
#include <deque>
#include <string>

namespace formflow::app {

/// Prints `iter  rel.change  pressure  time  left` lines to `out`; the time left
/// is estimated from the observed contraction of the relative change over the
/// last few iterations (one step's ratio is too noisy to extrapolate), and
/// never exceeds what the iterations left before `max_iterations` would take. With
/// `krylov` (an iterative back-end, solver.linear = "petsc") a last column shows the
/// Krylov iterations of each step. A record of another stage than the last (an error
/// estimate's level, an adaptive cycle: IterationRecord::stage) is headed by a line
/// naming it, and the time-left estimate restarts there.
class Monitor {
public:
  Monitor(std::FILE* out, Real tolerance, int max_iterations, bool krylov = false)
      : out_(out), tolerance_(tolerance), max_iterations_(max_iterations), krylov_(krylov) {}
  void header() const;
  void operator()(const solvers::IterationRecord& record);

private:
  std::FILE* out_;
  Real tolerance_;
  int max_iterations_;
  bool krylov_;
  std::deque<Real> recent_changes_; ///< the last few relative changes, oldest first
  std::string stage_;               ///< the stage of the last record (empty: the run's solve)
  Real elapsed_ = 0.0;
};

} // namespace formflow::app
