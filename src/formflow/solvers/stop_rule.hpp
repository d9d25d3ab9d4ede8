// SPDX-License-Identifier: MIT
// The stop rule shared by every nonlinear loop (secant, Newton, Uzawa): one
// place decides when an iteration has converged, diverged or produced garbage.
#pragma once

#include "formflow/solvers/stop_reason.hpp"

#include <cmath>
#include <optional>

namespace formflow::solvers {

/// A relative change this large means the iterates run away, not converge.
inline constexpr Real divergence_threshold = 1e6;

/// Why to stop after an iteration, or nothing to go on. `change` is the
/// relative change tested against the tolerance, `step_change` the one tested
/// for divergence (Newton: the step taken), `pressure` the monitored pressure;
/// `others_converged` lets a loop add its own condition (Uzawa: the multipliers).
inline std::optional<StopReason> stop_after_iteration(Real change, Real step_change, Real pressure,
                                                      Real tolerance,
                                                      bool others_converged = true) {
  if (!std::isfinite(change) || !std::isfinite(pressure)) return StopReason::NonFinite;
  if (step_change > divergence_threshold) return StopReason::Diverged;
  if (change < tolerance && others_converged) return StopReason::Converged;
  return std::nullopt;
}

} // namespace formflow::solvers
