// SPDX-License-Identifier: MIT
// The coarse start stage: the loop inside starts from the solution on coarser meshes.
#include "formflow/app/coarse_start.hpp"
#include "formflow/app/stages/stage.hpp"

#include <optional>

namespace formflow::app {

namespace {

/// Mesh sequencing (solver.coarse_levels, app/coarse_start.hpp) for the loops that take
/// it (SolvePlan::sequences_meshes): when the inner loop has no start of its own (not an
/// adaptive cycle's, not a later coupling step's) and the mesh is the plan's (its coarser
/// levels can be made), the levels are solved and the loop starts from the last one.
/// Its stop rule is the levels' (max(δ, 1e-2) each); its block in summary.json is
/// `coarse_iterations` and `coarse_mesh_sizes` (and `method`'s "from coarse meshes").
class CoarseStartStage final : public StageOf<CoarseStartStage> {
public:
  std::string_view name() const override { return "coarse start"; }

  template <int dim> void run_on(SolveState<dim>& state, const StageChain& inner) const {
    // Exact friction's coarse levels solve the Coulomb law with λ̂ = 0, i.e. stick penalty
    // r (the multipliers live at the fine Γ3 points only).
    std::optional<CoarseStart> coarse;
    if (state.mesh_from_plan && !state.start) {
      post::Results& results = state.results();
      coarse = coarse_start(state.run_plan(), state.problem->discretisation(), results.timing);
      if (coarse) {
        results.coarse_iterations = coarse->iterations;
        results.coarse_mesh_sizes = coarse->mesh_sizes;
        state.start = &coarse->velocity;
      }
    }
    inner.run(state);
    if (coarse) state.start = nullptr; // the start lived here
  }
};

} // namespace

const Stage& coarse_start_stage() {
  static const CoarseStartStage stage;
  return stage;
}

} // namespace formflow::app
