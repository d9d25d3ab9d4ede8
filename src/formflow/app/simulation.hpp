// SPDX-License-Identifier: MIT
// The whole solve of one case: mesh → dofs → secant iteration → post-processing.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"

#include <functional>

namespace formflow::app {

/// Called once per nonlinear iteration with its record (for the monitor).
using IterationCallback = std::function<void(const solvers::IterationRecord&)>;

struct Simulation {
  mesh::Mesh<2> mesh;
  post::Results results;
};

/// Solves `case_` (plane strain). Never throws for numerical trouble: a run
/// that does not converge returns results with the stop reason set.
Simulation simulate(const io::Case& case_, const IterationCallback& on_iteration = {});

}  // namespace formflow::app
