// SPDX-License-Identifier: MIT
// The tabular result files: iteration history and contact profile as CSV text.
#pragma once

#include "formflow/post/results.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <span>
#include <string>

namespace formflow::io {

/// history.csv: header `iteration,relative_change,pressure,seconds`, then one
/// row per record in the given order, reals as `{:.10g}`.
/// Throws InternalError naming row and column if a value is not finite.
std::string history_csv(std::span<const solvers::IterationRecord> history);

/// contact.csv: header `s,x,y,contact_pressure,friction_stress,slip_velocity,state,part`,
/// one row per sample in the given order (the solver sorts by s); `state` is
/// `stick` or `slip`, `part` is `container` or `die`.
/// Throws InternalError naming row and column if a value is not finite.
std::string contact_csv(std::span<const post::ContactSample> contact);

} // namespace formflow::io
