// SPDX-License-Identifier: MIT
// Which nonlinear loop solves which problem, said once: the case validation and the
// run plan both read this table (issue 13).
#pragma once

#include "formflow/solvers/linear_solver_kind.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace formflow::solvers {

/// What decides the loop: the formulation and constraints, the friction enforcement,
/// the symmetry and the method asked for (the case's keys, below io).
struct ProblemShape {
  bool mixed = false; ///< formulation.type = "mixed"
  /// Global pressure unknowns, a saddle point: Taylor–Hood, or the next.
  bool global_pressure = false;
  /// A discontinuous pressure kept as a saddle point (formulation.discontinuous_pressure).
  bool discontinuous_saddle_point = false;
  bool exact_incompressibility = false; ///< penalty.d = 0
  bool exact_contact = false;           ///< penalty.dN = 0
  bool exact_friction = false;          ///< friction.regularization = "none"
  bool exact_stick = false;             ///< friction.stick = "exact"
  bool nodal_contact = false;           ///< contact.normals = "nodes"
  bool axisymmetric = false;
  NonlinearMethod method = NonlinearMethod::Newton;    ///< solver.method
  LinearSolverKind linear = LinearSolverKind::Cholmod; ///< solver.linear
  /// solver.linear was set by the user (else it is the default, and a loop whose
  /// matrices the default cannot factorise takes a back-end that can).
  bool linear_given = false;
};

/// The nonlinear loops formflow has (solvers/*_iteration.hpp, augmented_*.hpp).
enum class LoopKind {
  Secant,            ///< the paper's Kachanov iteration
  Newton,            ///< Newton with the primal–dual tangent (newton_iteration.hpp)
  UzawaSecant,       ///< Uzawa steps of the exact constraints around secant
  SaddlePointSecant, ///< the Taylor–Hood saddle point by LU, Uzawa contact inside
  AugmentedSecant,   ///< exact friction: augmented Lagrangian around secant solves
  AugmentedNewton,   ///< exact friction: multipliers after every Newton step
};

/// A combination no loop serves: the keys involved (the last one set is blamed),
/// what is wrong and what would run.
struct Refusal {
  std::vector<std::string_view> keys;
  std::string message, hint;
};

/// The loop that solves `shape`, or why none does. Newton is asked for by default;
/// where it does not reach yet (exact constraints, Taylor–Hood) the secant-based
/// loop of the formulation runs and its name says so.
std::variant<LoopKind, Refusal> choose_loop(const ProblemShape& shape);

/// Whether the semismooth Newton of exact friction (exact stick on nodal contact points)
/// serves `shape` (its exact_stick and nodal_contact ignored): the exact law under the
/// Newton loop. The default friction.stick = "auto" resolves to it there.
bool exact_stick_serves(ProblemShape shape);

/// The matrices the loop hands to the linear solver.
MatrixStorage loop_storage(LoopKind loop);

/// The back-end that factorises the loop's matrices: solver.linear, or (when it was
/// not given and cannot serve them) UMFPACK. choose_loop(shape) refused the rest.
LinearSolverKind linear_solver_for(LoopKind loop, const ProblemShape& shape);

/// The loop's name in summary.json `method` (without the coarse-start suffix).
std::string loop_name(LoopKind loop, const ProblemShape& shape);

} // namespace formflow::solvers
