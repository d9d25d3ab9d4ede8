// SPDX-License-Identifier: MIT
// The secant step of the mixed problem with a continuous (Taylor–Hood)
// pressure: one global saddle-point solve per step (issue 5).
#pragma once

#include "formflow/assembly/saddle_point_system.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <optional>
#include <vector>

namespace formflow::solvers {

/// The lagged solve of secant_iteration for a problem whose attached
/// ConstraintMultipliers carry a global pressure (has_global_pressure). Each secant
/// step assembles the velocity matrix A(uⁿ) and factorises the saddle-point matrix
/// [A Bᵀ; B −d M] (assembly::SaddlePointSystem) with the step's solver, which must
/// take full, indefinite matrices (make_umfpack_solver); the pattern is analysed
/// once. The step solves for uⁿ⁺¹ and the pressure correction together; d = 0 needs
/// nothing else. With d_N = 0 the contact multipliers get Uzawa steps around the
/// same factorisation (as SecantSolve's), and the step counts as converged only
/// when they have settled. The pressure ends in the multipliers (global_pressure).
/// Each step's first solve starts from (w, 0): the lagged velocity and no pressure
/// correction (LinearSolver::set_initial_guess; an iterative back-end's Krylov start).
/// Building the saddle-point structure is timed as "setup".
template <int dim> class SaddlePointSolve final : public LaggedSolve {
public:
  SaddlePointSolve(FormingNonlinearProblem<dim>& problem, TimedLinearStep& linear);
  LaggedStep solve(const VectorX* w, VectorX& next) override;
  const assembly::LinearSystem& system() const override { return system_; }
  /// An iterative back-end's solves loosened (LinearSolver::set_solve_tolerance).
  bool loosen(Real reduction) override { return linear_.solver().set_solve_tolerance(reduction); }

private:
  /// A distributed solve's pressure correction (ghosted: the rank's own cells' dofs),
  /// whole on every rank. One rank: nothing to do.
  void replicate_pressure(VectorX& increment) const;

  FormingNonlinearProblem<dim>& problem_;
  TimedLinearStep& linear_;
  assembly::LinearSystem system_;
  std::optional<assembly::SaddlePointSystem<dim>> saddle_;
  bool blocks_decided_ = false, blocks_ = false; ///< LinearSolver::take_saddle_point_blocks
  std::vector<int> pressure_owner_; ///< distributed: each pressure dof's rank; else empty
};

} // namespace formflow::solvers
