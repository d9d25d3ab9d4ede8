// SPDX-License-Identifier: MIT
// The stop rule shared by every nonlinear loop (secant, Newton, Uzawa): one
// place decides when an iteration has converged, diverged or produced garbage.
#pragma once

#include "formflow/solvers/nonlinear_problem.hpp"
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

/// The stop after the problem's after-iteration hook: the driver's own reason to
/// stop (`own`, from stop_after_iteration with the driver's own inner conditions)
/// unless it is convergence the hook has not settled; else the hook's own reason.
inline std::optional<StopReason> stop_with_hook(std::optional<StopReason> own,
                                                const AfterIteration& after) {
  if (own && *own != StopReason::Converged) return own;
  if (after.stop) return after.stop;
  if (own && after.settled) return own;
  return std::nullopt;
}

} // namespace formflow::solvers
