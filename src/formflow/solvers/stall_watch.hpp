// SPDX-License-Identifier: MIT
// When a nonlinear loop has stopped making progress.
#pragma once

#include "formflow/core/types.hpp"

#include <limits>

namespace formflow::solvers {

/// Watches a merit that a converging loop drives to zero (exact friction's Newton
/// loop: max(velocity change, friction residual), both relative, both tested against
/// δ). The loop has stalled when `window` iterations in a row brought no new minimum:
/// a loop that converges, even slowly and not monotonically, keeps setting new minima;
/// one that cycles among active sets or sits at a round-off floor above δ does not,
/// and should say so (StopReason::Stalled) rather than run to max_iterations.
class StallWatch {
public:
  explicit StallWatch(int window) : window_(window) {}

  /// After an iteration with merit `merit`: true when the loop has stalled.
  bool stalled(Real merit) {
    if (merit < best_) {
      best_ = merit;
      since_best_ = 0;
      return false;
    }
    return ++since_best_ >= window_;
  }

  /// A new stage of the loop whose merit may start above the old minimum (exact stick: a
  /// held node released to slip, its excess over τ_f in the merit until the iterate
  /// settles again): minima are counted afresh.
  void restart() {
    best_ = std::numeric_limits<Real>::infinity();
    since_best_ = 0;
  }

private:
  int window_;
  Real best_ = std::numeric_limits<Real>::infinity();
  int since_best_ = 0;
};

} // namespace formflow::solvers
