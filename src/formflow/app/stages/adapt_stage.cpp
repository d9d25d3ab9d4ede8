// SPDX-License-Identifier: MIT
// The adaptive stage: the stages inside it on a sequence of meshes (app/adaptive_run.hpp).
#include "formflow/app/adaptive_run.hpp"
#include "formflow/app/stages/stage.hpp"

namespace formflow::app {

namespace {

/// Adaptive cycles (adapt.target_error > 0): solve, estimate, mark, remesh, interpolate,
/// each cycle's solve the stages inside this one (the estimate, the solve, ...). Its stop
/// rule is the target, adapt.max_cycles and adapt.max_dofs (simulate_adaptive); its
/// monitor lines are its cycles' ("adapt cycle 2, 5180 dofs"); its block in summary.json
/// is `adapt`.
class AdaptStage final : public StageOf<AdaptStage> {
public:
  std::string_view name() const override { return "adaptive cycles"; }

  template <int dim> void run_on(SolveState<dim>& state, const StageChain& inner) const {
    if constexpr (dim != 2) {
      FF_ASSERT(false, "the case validation refuses adaptivity of the solid channel");
      inner.run(state);
    } else {
      Simulation first = std::move(*state.simulation); // cycle 0's mesh, made by the run
      const CycleSolve solve_cycle = [&](const RunPlan& plan, mesh::Mesh<2>* mesh,
                                         const VectorX* start,
                                         const IterationCallback& on_iteration) {
        Simulation simulation;
        if (mesh)
          simulation.mesh = std::move(*mesh);
        else
          simulation = std::move(first);
        {
          SolveState<2> cycle;
          cycle.plan = &plan;
          cycle.simulation = &simulation;
          cycle.mesh_from_plan = mesh == nullptr;
          cycle.start = start;
          cycle.on_iteration = on_iteration;
          cycle.control = plan.solver;
          inner.run(cycle);
        } // the cycle's problem is released before the next mesh is made
        return simulation;
      };
      *state.simulation = simulate_adaptive(state.run_plan(), state.on_iteration, solve_cycle);
    }
  }
};

} // namespace

const Stage& adapt_stage() {
  static const AdaptStage stage;
  return stage;
}

} // namespace formflow::app
