// SPDX-License-Identifier: MIT
// The case seen by the capability table (solvers/capabilities.hpp).
#pragma once

#include "formflow/io/case.hpp"
#include "formflow/solvers/capabilities.hpp"

namespace formflow::io {

/// What of `case_` decides the nonlinear loop: formulation, exact constraints,
/// friction enforcement, symmetry, method and linear solver.
solvers::ProblemShape problem_shape(const Case& case_);

} // namespace formflow::io
