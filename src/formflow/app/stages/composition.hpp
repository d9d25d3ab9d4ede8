// SPDX-License-Identifier: MIT
// The one place the plan's stages are composed, and refused where they do not compose.
#pragma once

#include "formflow/app/run_plan.hpp"
#include "formflow/app/stages/stage.hpp"

#include <vector>

namespace formflow::app {

/// Whether the run makes its own meshes (the adaptive cycles) or solves on a mesh it is
/// given (simulate_on, simulate_from: a level of an estimate, a test's mesh).
enum class MeshOwnership { PlanMeshes, GivenMesh };

/// Refuses (InputError at the key's place: exit 2) a composition the stage table
/// (solvers/stage_table.hpp) refuses, with the words the case validation uses.
void refuse_composition(const RunPlan& plan);

/// The stages of `plan`, outermost first, after refuse_composition: the registry below
/// in its order, each stage whose switch the plan sets. Every chain ends in a solve.
std::vector<const Stage*> compose_stages(const RunPlan& plan, MeshOwnership meshes);

} // namespace formflow::app
