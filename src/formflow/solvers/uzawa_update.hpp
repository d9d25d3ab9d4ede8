// SPDX-License-Identifier: MIT
// One Uzawa update of the exact-constraint multipliers, shared by the Uzawa
// loop around CHOLMOD and the saddle-point loop's exact-contact steps.
#pragma once

#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/solvers/stop_reason.hpp"
#include "formflow/solvers/uzawa_settling.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace formflow::solvers {

/// Updates the problem's multipliers from the velocity just solved for
/// (λ ← λ + r M⁻¹B u, λ_N ← λ_N + r_N u_N) and sets `settled` as `settling`
/// decides; NonFinite when the change is not a number.
template <int dim>
std::optional<StopReason> update_multipliers(const assembly::FormingProblem<dim>& problem,
                                             const VectorX& velocity, UzawaSettling& settling,
                                             bool& settled) {
  assembly::ConstraintMultipliers<dim>& multipliers = *problem.multipliers();
  std::vector<Real> normal_velocity;
  if (multipliers.is_exact_contact())
    for (const auto& point : problem.contact_state(velocity))
      normal_velocity.push_back(point.normal_velocity);
  const Real change = multipliers.update(velocity, normal_velocity);
  if (!std::isfinite(change)) return StopReason::NonFinite;
  settled = settling.settled(change);
  return std::nullopt;
}

} // namespace formflow::solvers
