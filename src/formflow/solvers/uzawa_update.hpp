// SPDX-License-Identifier: MIT
// One Uzawa update of the exact-constraint multipliers, shared by the Uzawa
// steps around CHOLMOD and the saddle-point loop's exact-contact steps.
#pragma once

#include "formflow/solvers/nonlinear_problem.hpp"
#include "formflow/solvers/uzawa_settling.hpp"

#include <cmath>
#include <optional>

namespace formflow::solvers {

/// Updates the problem's constraint multipliers from the velocity just solved for
/// and sets `settled` as `settling` decides; NonFinite when the change is not a number.
inline std::optional<StopReason> uzawa_update(NonlinearProblem& problem, const VectorX& velocity,
                                              UzawaSettling& settling, bool& settled) {
  const Real change = problem.update_constraint_multipliers(velocity);
  if (!std::isfinite(change)) return StopReason::NonFinite;
  settled = settling.settled(change);
  return std::nullopt;
}

} // namespace formflow::solvers
