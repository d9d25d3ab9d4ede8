// SPDX-License-Identifier: MIT
#include "formflow/app/distributed_run.hpp"

#include "formflow/app/solve_plan.hpp"
#include "formflow/app/stop_signals.hpp"
#include "formflow/core/error.hpp"

#include <fmt/format.h>

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

void check_distributed(const io::Case& case_) {
  const assembly::Distribution& run = distribution();
  if (!run.distributed()) return;
  const auto refuse = [&](const std::string& key, const std::string& what,
                          const std::string& hint) {
    const auto where = case_.key_locations.find(key);
    const std::string file = where == case_.key_locations.end() ? case_.source : where->second.file;
    const int line = where == case_.key_locations.end() ? 0 : where->second.line;
    throw InputError(
        file, line, key,
        fmt::format("on {} MPI ranks: a distributed run (docs/petsc.md) {}", run.size, what), hint);
  };
  if (case_.solver.linear != solvers::LinearSolverKind::Petsc)
    refuse("solver.linear", "needs the PETSc back-end",
           "set solver.linear = \"petsc\", or run as one process");
  if (case_.manufactured != physics::ManufacturedSolution::None)
    refuse("verification.solution", "solves forming cases only", "run it as one process");
  if (case_.thermal.enabled)
    refuse("thermal.enabled", "has no heat solve yet", "run hot forming as one process");
  if (case_.solver.load_error != solvers::LoadErrorMethod::None)
    refuse("solver.load_error", "has no error estimate yet",
           "set solver.load_error = \"none\", or run as one process");
  const SolvePlan plan = make_solve_plan(case_);
  if (plan.loop == solvers::LoopKind::Secant) return;
  if (case_.solver.method == solvers::NonlinearMethod::Newton)
    refuse("solver.method", "runs the secant iteration only (no Newton tangent yet)",
           "set solver.method = \"secant\"");
  if (plan.loop == solvers::LoopKind::AugmentedSecant)
    refuse("friction.regularization", "serves the regularised friction only",
           "set friction.regularization to the d_T regularisation (the paper's), or run as one "
           "process");
  if (plan.loop == solvers::LoopKind::SaddlePointSecant) {
    if (case_.formulation.discontinuous == assembly::DiscontinuousPressure::SaddlePoint)
      refuse("formulation.discontinuous_pressure",
             "condenses the pressure only (no saddle point yet)",
             "set formulation.discontinuous_pressure = \"condensed\", or run as one process");
    refuse("formulation.pressure", "condenses the pressure only (no saddle point yet)",
           "set formulation.pressure = \"P1disc\" or \"P0\", or run as one process");
  }
  refuse("penalty.d", "serves penalised constraints only (d > 0, d_N > 0: no Uzawa steps yet)",
         "give penalty.d and penalty.dN positive values, or run as one process");
}

} // namespace formflow::app
