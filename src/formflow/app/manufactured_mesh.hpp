// SPDX-License-Identifier: MIT
// The mesh of a manufactured-solution run: the unit square or cube.
#pragma once

#include "formflow/app/run_plan.hpp"
#include "formflow/mesh/any_mesh.hpp"

namespace formflow::app {

/// The box mesh of a manufactured solution (verification.solution ≠ none): the unit
/// square (or cube, mesh.dimension = 3) in 1/mesh.size cells per direction, of the
/// element's order, with mesh.distortion (app/stages/manufactured_stage.cpp).
mesh::AnyMesh manufactured_mesh(const RunPlan& plan);

} // namespace formflow::app
