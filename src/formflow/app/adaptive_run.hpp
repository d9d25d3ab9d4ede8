// SPDX-License-Identifier: MIT
// Adaptive refinement driven by the load's error indicators ([adapt], issue 17).
#pragma once

#include "formflow/app/simulation.hpp"

namespace formflow::app {

/// Solves `case_` on a sequence of meshes (docs/error-estimation.md, "Adaptivity"):
/// cycle 0 is the plain run on the case's mesh; after each cycle the load's error
/// estimate (solver.load_error; "none" is taken as "refined") is compared with
/// adapt.target_error · |p_h|, the cells are marked by Dörfler's rule on |η_K|
/// (adapt.fraction), and Gmsh remeshes the channel with half the size in the marked
/// cells and the same size elsewhere (mesh/gmsh_sized_channel.hpp); Newton starts
/// from the previous solution interpolated to the new mesh. Stops at the target,
/// after adapt.max_cycles solves, before a mesh expected to exceed adapt.max_dofs,
/// or at a cycle that did not converge or has no estimate. Returns the last
/// cycle's simulation with `results.adapt` recording every cycle and "total" the
/// whole run's wall time. Plane channels only (the case validation refuses others).
Simulation simulate_adaptive(const io::Case& case_, const IterationCallback& on_iteration = {});

} // namespace formflow::app
