// SPDX-License-Identifier: MIT
// The thermal coupling stage: the loop inside, again at each coupling step's temperature.
#include "formflow/app/stages/stage.hpp"
#include "formflow/app/thermal_coupling.hpp"

#include "formflow/solvers/pattern_reuse.hpp"

namespace formflow::app {

namespace {

/// Hot forming (app/thermal_coupling.hpp, docs/thermal.md): the stages inside (the coarse
/// start, the loop) run at the billet's temperature, then again after each heat solve
/// from the last velocity, with one linear solver whose symbolic analysis serves every
/// step (the pattern is the same). Its stop rule is thermal.coupling_tolerance and
/// thermal.max_coupling_iterations; its monitor lines are the coupling records
/// (IterationRecord::coupling); its block in summary.json is `thermal`.
class ThermalStage final : public StageOf<ThermalStage> {
public:
  std::string_view name() const override { return "thermal coupling"; }

  template <int dim> void run_on(SolveState<dim>& state, const StageChain& inner) const {
    const RunPlan& plan = state.run_plan();
    const SolvePlan& solve = plan.solve;
    state.solver = solvers::reuse_analysis(solvers::make_linear_solver(
        solve.linear, solvers::loop_storage(solve.loop), plan.solver.petsc_options));
    const VectorX* first_start = state.start; // an adaptive cycle's, or none
    const FlowSolve solve_flow = [&](const VectorX* start, Real tolerance) {
      state.control.tolerance = tolerance; // inexact staggering
      state.start = start ? start : first_start;
      inner.run(state);
      return state.outcome;
    };
    state.outcome =
        couple_thermal(plan.thermal, plan.problem.friction, plan.solver.tolerance, *state.problem,
                       solve_flow, state.on_iteration, state.multipliers, state.results());
    state.start = first_start;
    state.control = plan.solver;
    state.solver.reset();
  }
};

} // namespace

const Stage& thermal_stage() {
  static const ThermalStage stage;
  return stage;
}

} // namespace formflow::app
