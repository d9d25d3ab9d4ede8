// SPDX-License-Identifier: MIT
// The solve stage: the forming problem on the mesh, the loop inside, the results after.
#include "formflow/app/stages/stage.hpp"

#include "formflow/post/exit_flow.hpp"
#include "formflow/post/post_process.hpp"

#include <memory>

namespace formflow::app {

namespace {

/// Mesh → converged state: builds the problem (and the mixed formulation's multipliers)
/// for the stages inside it, and after them evaluates the results (summary.json's
/// method, stop reason, history, pressures, fields). The problem stays in the state for
/// the stages outside it (the load's estimate).
class SolveStage final : public StageOf<SolveStage> {
public:
  std::string_view name() const override { return "solve"; }

  template <int dim> void run_on(SolveState<dim>& state, const StageChain& inner) const {
    const RunPlan& plan = state.run_plan();
    post::Results& results = state.results();
    const mesh::Mesh<dim>& mesh = state.mesh();
    {
      ScopedTimer timer(results.timing, "setup");
      state.problem = std::make_unique<assembly::FormingProblem<dim>>(mesh, plan.problem);
    }
    // Mixed formulation and exact constraints (issue 5): pressures condensed cell
    // by cell keep the velocity system SPD, so CHOLMOD serves every formulation.
    // Exact friction (friction.regularization = "none") with d = 0 or d_N = 0 is
    // refused by the case validation: one multiplier loop at a time.
    if (plan.formulation.type == assembly::FormulationType::Mixed ||
        plan.problem.penalty.d_n == 0) {
      state.constraint_multipliers = std::make_unique<assembly::ConstraintMultipliers<dim>>(
          mesh, plan.problem.penalty, plan.formulation, state.problem->full_rule(),
          state.problem->n_contact_points(), state.problem->discretisation().axisymmetric());
      state.problem->attach_multipliers(state.constraint_multipliers.get());
    }
    inner.run(state);
    solvers::SecantOutcome& outcome = state.outcome;
    results.method = plan.solve.name(!results.coarse_mesh_sizes.empty());
    results.stop_reason = outcome.stop_reason;
    results.history = std::move(outcome.history);
    results.iterations = static_cast<int>(results.history.size());
    // Exact friction by Newton reports stick where the slip is below what δ resolves.
    const Real stick_speed = plan.solve.loop == solvers::LoopKind::AugmentedNewton
                                 ? plan.solver.tolerance * plan.problem.process.speed
                                 : 0.0;
    post::evaluate_results(*state.problem, outcome.velocity, results, &state.multipliers,
                           stick_speed);
    if constexpr (dim == 3)
      if (results.exit.present && plan.mesh.solid.section == mesh::ChannelSection::Profile)
        results.exit.edges =
            post::profile_exit_edges(*state.problem, outcome.velocity, plan.mesh.solid.profile);
    if (results.thermal.enabled) results.fields.temperature = results.thermal.temperature;
    if (state.estimate_condition)
      state.simulation->reciprocal_condition = condition_at(*state.problem, outcome.velocity);
  }
};

} // namespace

const Stage& solve_stage() {
  static const SolveStage stage;
  return stage;
}

} // namespace formflow::app
