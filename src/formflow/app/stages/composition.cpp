// SPDX-License-Identifier: MIT
// The stage registry: which stages a plan has and in which order they nest.
#include "formflow/app/stages/composition.hpp"

namespace formflow::app {

namespace {

/// A stage and when a plan has it. The order is the nesting, outermost first: the
/// adaptive cycles run whole estimated solves; the estimate reads the solved problem;
/// the solve stage builds the problem for the stages inside it; the coupling steps run
/// the loop (from the coarse start, the first time) at each temperature.
struct StageEntry {
  bool (*applies)(const RunPlan& plan, MeshOwnership meshes);
  const Stage& (*stage)();
};

bool forming(const RunPlan& plan) {
  return !plan.is_manufactured();
}

constexpr StageEntry stage_registry[] = {
    {[](const RunPlan& plan, MeshOwnership meshes) {
       return meshes == MeshOwnership::PlanMeshes && plan.adapt.enabled();
     },
     adapt_stage},
    {[](const RunPlan& plan, MeshOwnership) { return forming(plan); }, estimate_stage},
    {[](const RunPlan& plan, MeshOwnership) { return plan.is_manufactured(); }, manufactured_stage},
    {[](const RunPlan& plan, MeshOwnership) { return forming(plan); }, solve_stage},
    {[](const RunPlan& plan, MeshOwnership) { return forming(plan) && plan.thermal.enabled; },
     thermal_stage},
    {[](const RunPlan& plan, MeshOwnership) {
       return forming(plan) && plan.solve.sequences_meshes();
     },
     coarse_start_stage},
    {[](const RunPlan& plan, MeshOwnership) { return forming(plan); }, loop_stage},
};

} // namespace

void refuse_composition(const RunPlan& plan) {
  if (const auto refusal = solvers::refused_composition(plan.stages))
    throw plan.keys.error(refusal->key, refusal->message, refusal->hint);
}

std::vector<const Stage*> compose_stages(const RunPlan& plan, MeshOwnership meshes) {
  refuse_composition(plan);
  std::vector<const Stage*> stages;
  for (const StageEntry& entry : stage_registry)
    if (entry.applies(plan, meshes)) stages.push_back(&entry.stage());
  return stages;
}

} // namespace formflow::app
