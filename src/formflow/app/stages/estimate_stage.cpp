// SPDX-License-Identifier: MIT
// The estimate stage: the load's error bar of the solve inside it (app/load_error.hpp).
#include "formflow/app/load_error.hpp"
#include "formflow/app/stages/stage.hpp"

namespace formflow::app {

namespace {

/// The load's error bar (docs/error-estimation.md) after the solve inside: one adjoint
/// solve on the mesh refined once, or the coarser levels, by solver.load_error ("auto"
/// resolved by the mesh). It has no stop rule of its own (its levels' solves stop at δ);
/// its monitor lines are its levels' ("error estimate: the mesh refined once, ...");
/// its block in summary.json is `load_error`, and the cells' indicators a field.
class EstimateStage final : public StageOf<EstimateStage> {
public:
  std::string_view name() const override { return "error estimate"; }

  template <int dim> void run_on(SolveState<dim>& state, const StageChain& inner) const {
    inner.run(state);
    FF_ASSERT(state.problem, "the estimate reads the solve stage's problem");
    post::Results& results = state.results();
    results.load_error = load_error_of(state.run_plan(), *state.problem, state.outcome.velocity,
                                       results.pressure.ram_reaction, state.mesh_from_plan,
                                       results.converged(), results.timing, state.on_iteration);
    results.fields.cell_load_error = results.load_error.cell_indicators;
  }
};

} // namespace

const Stage& estimate_stage() {
  static const EstimateStage stage;
  return stage;
}

} // namespace formflow::app
