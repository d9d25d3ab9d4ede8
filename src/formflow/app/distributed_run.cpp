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
  const SolvePlan plan = make_solve_plan(case_);
  // Exact friction's multipliers are updated per Γ3 point from the replicated velocity,
  // alike on every rank; its exact stick condenses T, which a rank holds a share of.
  if (plan.shape.exact_stick)
    refuse("friction.stick", "imposes no exact stick yet (it condenses the whole tangent)",
           "set friction.stick = \"augmented\", or run as one process");
  if (plan.loop == solvers::LoopKind::Secant || plan.loop == solvers::LoopKind::Newton ||
      plan.loop == solvers::LoopKind::AugmentedSecant ||
      plan.loop == solvers::LoopKind::AugmentedNewton)
    return;
  if (plan.loop == solvers::LoopKind::SaddlePointSecant) {
    // A discontinuous pressure kept as a saddle point runs distributed: each pressure dof
    // is one cell's, so one rank's (assembly/saddle_point_system.hpp). Taylor–Hood's
    // vertex pressure couples the ranks' cells and has no distributed pin yet.
    if (case_.formulation.discontinuous != assembly::DiscontinuousPressure::SaddlePoint)
      refuse("formulation.pressure", "has no Taylor–Hood saddle point yet",
             "set formulation.pressure = \"P1disc\" or \"P0\" (with "
             "formulation.discontinuous_pressure = \"saddle_point\" for the iterative path), "
             "or run as one process");
    return;
  }
  // Exact constraints by Uzawa steps (d = 0 with a condensed pressure, d_N = 0): each
  // rank steps its own cells' multipliers, the Γ3 points' alike from the exchanged
  // contact state (ConstraintMultipliers::update, session 16).
  FF_ASSERT(plan.loop == solvers::LoopKind::UzawaSecant, "every loop kind is handled above");
}

io::Case load_run_case(const std::string& path, std::vector<io::Override> overrides) {
  io::Case case_ = io::load_case(path, overrides);
  if (!distribution().distributed()) return case_;
  bool reload = false;
  if (case_.key_locations.count("solver.linear") == 0 &&
      case_.solver.linear != solvers::LinearSolverKind::Petsc) {
    // Left at its default (CHOLMOD, serial only): PETSc, as if given last on the command line.
    overrides.emplace_back("solver.linear", "petsc");
    reload = true;
  }
  if (reload) case_ = io::load_case(path, overrides);
  if (case_.key_locations.count("friction.stick") == 0 &&
      make_solve_plan(case_).shape.exact_stick) {
    // The exact law's default under Newton (exact stick on nodal points) condenses the whole
    // tangent, which no rank holds: the augmented multipliers on the face points instead,
    // said once, since a serial run of the same case would take the other discretisation.
    fmt::print(stderr,
               "note: friction.stick = \"augmented\" on {} ranks (exact stick runs as one "
               "process; docs/petsc.md)\n",
               distribution().size);
    overrides.emplace_back("friction.stick", "augmented");
    case_ = io::load_case(path, overrides);
  }
  return case_;
}

} // namespace formflow::app
