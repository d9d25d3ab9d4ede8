// SPDX-License-Identifier: MIT
// Which outer loops compose, said once: the case validation and the run plan's
// composition (app/stages/composition.cpp) both read this table (issue 43).
#pragma once

#include <optional>
#include <string>

namespace formflow::solvers {

/// The outer loops (stages) a run has around its solve, and what of the solve they
/// depend on: the case's keys, below io (io/stage_set.hpp fills it from a case, the
/// run plan adds the ranks).
struct StageSet {
  bool manufactured = false; ///< verification.solution ≠ "none": the manufactured run
  bool thermal = false;      ///< thermal.enabled: the heat coupling around the flow loop
  bool adapt = false;        ///< adapt.target_error > 0: the adaptive cycles
  /// solver.load_error given as "linearized": the adjoint at u prolonged to the refined
  /// mesh, no settle there (its "refined" and "coarser" levels are whole runs).
  bool linearized_estimate_asked = false;
  int ranks = 1; ///< MPI ranks (> 1: a distributed run, issue 20)
  // What the adaptive cycles and the distributed run ask of the solve inside them.
  bool exact_friction = false;          ///< friction.regularization = "none"
  bool exact_incompressibility = false; ///< formulation.type = "mixed" with penalty.d = 0
  bool exact_contact = false;           ///< penalty.dN = 0
  bool newton = true;                   ///< solver.method = "newton"
  bool petsc = false;                   ///< solver.linear = "petsc"
  bool exact_stick = false;             ///< friction.stick resolved to "exact"
  /// The loop is the continuous (Taylor–Hood) saddle point, whose vertex pressure
  /// couples the ranks' cells.
  bool taylor_hood_saddle_point = false;
};

/// A composition no run serves: the key to blame (the outer stage's switch is
/// `stage_key`, the one to clear for the run without that stage), what is wrong and
/// what would run.
struct StageRefusal {
  std::string key;       ///< e.g. "thermal.enabled"
  std::string stage_key; ///< the outer stage's switch: "adapt.target_error", "mpi ranks"
  std::string message, hint;
};

/// The first row of the table that refuses `stages`, or nothing when they compose.
/// Rows in the order they are checked: adaptivity (with a manufactured solution, exact
/// friction, exact constraints, the secant method), hot forming (with the linearised
/// estimate asked for), then a distributed run (another back-end than PETSc, a
/// manufactured solution, exact stick, Taylor–Hood).
std::optional<StageRefusal> refused_composition(const StageSet& stages);

} // namespace formflow::solvers
