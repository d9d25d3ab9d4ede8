// SPDX-License-Identifier: MIT
// The "coarser" estimate: the loads on the structured channel at 2h and 4h.
#pragma once

#include "formflow/app/run.hpp"
#include "formflow/app/run_plan.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/post/results.hpp"

namespace formflow::app {

/// The "coarser" estimate (post::coarser_levels_bound) of a run whose load is `load`:
/// the loads on the structured channel at 2h (from u restricted) and 4h (from u_{2h}
/// restricted), each solved to δ, their ratio of differences, and the regularisations'
/// offset measured on 2h (from u_{2h}: a quarter of the run's dofs; on the sticking ram
/// the offset shrinks with h, −3.9e-4 at h = 1 to −1.0e-4 at 1/16, so 2h's is the
/// larger). `own_loop`: the levels are solved by the run's loop, not by Newton.
template <int dim>
post::LoadErrorEstimate
coarser_levels_estimate(const RunPlan& plan, const assembly::FormingProblem<dim>& problem,
                        const VectorX& u, Real load, bool own_loop, PhaseTimes& times,
                        const IterationCallback& on_iteration);

} // namespace formflow::app
