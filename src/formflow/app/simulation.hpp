// SPDX-License-Identifier: MIT
// The whole solve of one case: mesh → dofs → secant iteration → post-processing.
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/post/error_norms.hpp"
#include "formflow/post/results.hpp"

#include <functional>
#include <optional>

namespace formflow::app {

/// Called once per nonlinear iteration with its record (for the monitor).
using IterationCallback = std::function<void(const solvers::IterationRecord&)>;

struct Simulation {
  mesh::Mesh<2> mesh;
  post::Results results;
  /// Error against the exact field: only for a manufactured solution (verification.solution).
  std::optional<post::ErrorNorms> errors;
  /// CHOLMOD rcond of K(u) at the final velocity, when asked for.
  std::optional<Real> reciprocal_condition;
};

/// Solves `case_` (plane strain). Never throws for numerical trouble: a run
/// that does not converge returns results with the stop reason set. A case
/// with a manufactured solution is solved by simulate_manufactured.
Simulation simulate(const io::Case& case_, const IterationCallback& on_iteration = {},
                    bool estimate_condition = false);

/// The manufactured-solution problem of `case_` (verification.solution ≠ none):
/// unit square, box mesh with the case's distortion, exact velocity on the
/// whole boundary, body force; `errors` filled (app/manufactured_simulation.cpp).
Simulation simulate_manufactured(const io::Case& case_, const IterationCallback& on_iteration = {},
                                 bool estimate_condition = false);

/// The discrete problem's parameters taken from `case_`.
assembly::ProblemSettings problem_settings(const io::Case& case_);

/// CHOLMOD rcond of the secant matrix K(u) of `problem` at velocity `u`.
Real condition_at(const assembly::FormingProblem<2>& problem, const VectorX& u);

} // namespace formflow::app
