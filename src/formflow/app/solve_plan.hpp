// SPDX-License-Identifier: MIT
// The solve plan: which loop, linear solver, coarse levels and multiplier
// augmentation a case runs with, built once from the case (issue 13; the translation
// is app/case_translation.cpp).
#pragma once

#include "formflow/solvers/capabilities.hpp"

#include <string>

namespace formflow::app {

struct SolvePlan {
  solvers::ProblemShape shape;
  solvers::LoopKind loop = solvers::LoopKind::Newton;
  solvers::LinearSolverKind linear = solvers::LinearSolverKind::Cholmod;
  /// Mesh sequencing (solver.coarse_levels) for the loops that take it (sequences_meshes);
  /// 0 for the others.
  int coarse_levels = 0;
  /// Exact friction's augmentation r in units of 1/d_N: friction.newton_augmentation for
  /// the Newton loop (its tangent carries the stick penalty), friction.augmentation for
  /// the secant one.
  Real friction_augmentation = 1.0;

  bool is_newton() const {
    return loop == solvers::LoopKind::Newton || loop == solvers::LoopKind::AugmentedNewton;
  }
  /// Whether the loop starts from coarse-mesh solutions (app/coarse_start.hpp): the Newton
  /// loops, and the secant loop of a discontinuous pressure kept as a saddle point (the
  /// iterative PETSc path, whose fine-mesh steps are the expensive ones). Taylor–Hood's
  /// saddle point (UMFPACK) and the Uzawa and plain secant loops start as before.
  bool sequences_meshes() const {
    return is_newton() ||
           (loop == solvers::LoopKind::SaddlePointSecant && shape.discontinuous_saddle_point);
  }
  /// summary.json `method`: the loop's name, "from coarse meshes" when a coarse start ran.
  std::string name(bool coarse_start_ran) const;
};

} // namespace formflow::app
