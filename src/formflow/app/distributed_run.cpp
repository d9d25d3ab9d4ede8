// SPDX-License-Identifier: MIT
#include "formflow/app/distributed_run.hpp"

#include "formflow/app/stop_signals.hpp"
#include "formflow/core/error.hpp"

namespace formflow::app {

namespace {

assembly::Distribution& stored() {
  static assembly::Distribution distribution;
  return distribution;
}

} // namespace

void set_distribution(assembly::Distribution distribution) {
  stored() = std::move(distribution);
}

const assembly::Distribution& distribution() {
  return stored();
}

void stop_if_signalled() {
  const assembly::Distribution& run = distribution();
  if (!run.distributed()) {
    throw_if_signalled();
    return;
  }
  Real seen = stop_signal() != 0 ? 1.0 : 0.0;
  run.sum_over_ranks(std::span<Real>(&seen, 1));
  if (seen > 0) throw Stopped("stopped by a signal during the solve");
}

} // namespace formflow::app
