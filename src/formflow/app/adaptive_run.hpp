// SPDX-License-Identifier: MIT
// Adaptive refinement driven by the load's error indicators ([adapt], issue 17).
#pragma once

#include "formflow/app/run.hpp"

#include <functional>

namespace formflow::app {

/// The stages inside the adaptive cycles, run on one cycle's mesh: `mesh` null for cycle
/// 0 (the plan's own mesh, made by the run), else a cycle's mesh (moved from) with the
/// loop's start `start` (a full dof vector on it). The plan is the cycle's (its estimate's
/// method and target); the returned simulation holds the mesh and its results.
using CycleSolve =
    std::function<Simulation(const RunPlan& plan, mesh::Mesh<2>* mesh, const VectorX* start,
                             const IterationCallback& on_iteration)>;

/// Solves `plan` on a sequence of meshes (docs/error-estimation.md, "Adaptivity"):
/// cycle 0 is the plain run on the plan's mesh; after each cycle the load's error
/// estimate (solver.load_error; "none" is taken as "refined") is compared with
/// adapt.target_error · |p_h|, the cells are marked by Dörfler's rule on |η_K|
/// (adapt.fraction), and Gmsh remeshes the channel with half the size in the marked
/// cells and the same size elsewhere (mesh/gmsh_sized_channel.hpp); Newton starts
/// from the previous solution interpolated to the new mesh. Stops at the target,
/// after adapt.max_cycles solves, before a mesh expected to exceed adapt.max_dofs,
/// or at a cycle that did not converge or has no estimate. Each cycle is `solve_cycle`
/// (the stages inside the adaptive stage, app/stages/adapt_stage.cpp). Returns the last
/// cycle's simulation with `results.adapt` recording every cycle. Plane channels only
/// (the case validation refuses others).
Simulation simulate_adaptive(const RunPlan& plan, const IterationCallback& on_iteration,
                             const CycleSolve& solve_cycle);

} // namespace formflow::app
