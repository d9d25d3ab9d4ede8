// SPDX-License-Identifier: MIT
// Where an iterative PETSc solve starts and when it may stop: a guess, and inexact solves.
#pragma once

#include "formflow/core/types.hpp"

#include <petscksp.h>

#include <optional>

namespace formflow::solvers::petsc {

/// Whether `ksp` iterates (anything but preonly: a direct solve).
bool is_iterative(KSP ksp);

/// The next solve's start (LinearSolver::set_initial_guess) and its stopping tolerance
/// (LinearSolver::set_solve_tolerance) for an iterative back-end. PETSc's stop test
/// stays relative to the right-hand side's norm, so a guess makes the solve as accurate
/// as from zero in fewer iterations; a loop that asks for a residual reduction of the
/// start (secant_iteration's inexact steps) gets that reduction times ‖b − A x₀‖/‖b‖ as
/// the tolerance where that is looser than the own one.
class KrylovStart {
public:
  void set_guess(VectorX guess) { guess_ = std::move(guess); }
  /// The guess if it has `size` entries; cleared either way (it serves one solve).
  std::optional<VectorX> take_guess(Index size);

  void ask_reduction(Real reduction) { asked_reduction_ = reduction; }
  Real asked_reduction() const { return asked_reduction_; }

  /// Whether solves may be loosened: `ksp` iterates and -formflow_inexact_steps (read
  /// here, so it counts as used) is not 0. Decided at the first call with a KSP; true
  /// while there is none yet.
  bool inexact_allowed(KSP ksp);

  /// Sets the tolerance of the coming KSPSolve: the own one (formflow's default or
  /// -ksp_rtol, read at the first call), or the asked reduction's if looser. Needs
  /// `rhs` and the start in `solution` (`guessed`: a nonzero start).
  void apply_tolerance(KSP ksp, Mat matrix, Vec rhs, Vec solution, bool guessed);

private:
  VectorX guess_;
  Real own_tolerance_ = 0;   ///< -ksp_rtol as configured (0: not read yet)
  Real asked_reduction_ = 0; ///< 0: the own tolerance
  std::optional<bool> inexact_allowed_;
};

} // namespace formflow::solvers::petsc
