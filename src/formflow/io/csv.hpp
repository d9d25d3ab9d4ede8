// SPDX-License-Identifier: MIT
// The tabular result files: iteration history and contact profile as CSV text.
#pragma once

#include "formflow/post/results.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <span>
#include <string>

namespace formflow::io {

/// The first line of a CSV file of a run that stopped for `stop_reason` other
/// than Converged: `# not converged: <stop_reason>`; "" for a converged run.
/// A comment line, so readers told about `#` comments (pandas `comment='#'`,
/// numpy `loadtxt`, gnuplot) skip it, and one that does not sees a malformed
/// first row instead of silently taking an unconverged iterate for a result.
std::string not_converged_line(solvers::StopReason stop_reason);

/// history.csv: not_converged_line(stop_reason), header
/// `iteration,relative_change,pressure,seconds`, then one row per record in
/// the given order, reals as `{:.10g}`.
/// Throws InternalError naming row and column if a value is not finite.
std::string history_csv(std::span<const solvers::IterationRecord> history,
                        solvers::StopReason stop_reason = solvers::StopReason::Converged);

/// contact.csv: not_converged_line(stop_reason), header
/// `s,x,y,contact_pressure,friction_stress,slip_velocity,state,part`,
/// one row per sample in the given order (the solver sorts by s); `state` is
/// `stick` or `slip`, `part` is `container` or `die`. For a solid run
/// (`dimension` 3) the coordinates are `x,y,z` and there is no `s` column:
/// Γ3 is a surface, which has no arc length (post::contact_profile).
/// Throws InternalError naming row and column if a value is not finite.
std::string contact_csv(std::span<const post::ContactSample> contact,
                        solvers::StopReason stop_reason = solvers::StopReason::Converged,
                        int dimension = 2);

} // namespace formflow::io
