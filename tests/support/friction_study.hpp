// SPDX-License-Identifier: MIT
// Solves the benchmark with exact or regularised friction and keeps what the
// friction tests inspect: velocity, multipliers, the Γ3 state and the results.
#pragma once

#include "formflow/app/simulation.hpp"
#include "formflow/app/solve_plan.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/augmented_lagrangian.hpp"
#include "formflow/solvers/augmented_newton.hpp"

#include <cmath>
#include <memory>

namespace formflow::testing {

/// One solved case. The mesh is owned here because the problem refers to it.
struct FrictionSolve {
  std::unique_ptr<mesh::Mesh<2>> mesh;
  std::unique_ptr<assembly::FormingProblem<2>> problem;
  VectorX velocity;
  assembly::FrictionMultipliers<2> multipliers;
  solvers::StopReason stop_reason = solvers::StopReason::MaxIterations;
  int iterations = 0;
  int augmentations = 0;
  Real multiplier_change = 0.0;
  Real friction_residual = 0.0; ///< Coulomb residual of the last update (Newton's stop rule)
  post::Results results;

  bool converged() const { return stop_reason == solvers::StopReason::Converged; }
  /// Γ3 state at the final velocity, with the final multipliers (exact friction).
  std::vector<assembly::ContactPoint<2>> contact() const {
    return problem->contact_state(velocity, &multipliers);
  }
};

/// The paper's benchmark from a Case (SPEC §4 defaults plus the caller's edits),
/// solved by the loop `formflow run` takes for solver.method, from the
/// constant-viscosity start (no coarse levels): exact friction by the augmented
/// Lagrangian around Newton (the plan's AugmentedNewton loop) or around the secant
/// iteration; regularised friction by Newton or the secant iteration.
inline FrictionSolve solve_friction_case(const io::Case& case_) {
  FrictionSolve solve;
  solve.mesh = std::make_unique<mesh::Mesh<2>>(mesh::make_channel_mesh(
      case_.mesh.geometry, case_.mesh.size, fem::element_order(case_.element)));
  solve.problem =
      std::make_unique<assembly::FormingProblem<2>>(*solve.mesh, app::problem_settings(case_));
  auto solver = solvers::make_cholmod_solver();
  PhaseTimes times;
  const bool newton = case_.solver.method == solvers::NonlinearMethod::Newton;
  solvers::FormingNonlinearProblem<2> nonlinear(*solve.problem);
  if (app::make_solve_plan(case_).loop == solvers::LoopKind::AugmentedNewton) {
    auto outcome = solvers::augmented_newton<2>(nonlinear, *solver, case_.solver, {}, times);
    solve.velocity = outcome.solve.velocity;
    solve.stop_reason = outcome.solve.stop_reason;
    solve.iterations = static_cast<int>(outcome.solve.history.size());
    solve.multipliers = outcome.multipliers;
    solve.augmentations = outcome.augmentations;
    solve.multiplier_change = outcome.multiplier_change;
    solve.friction_residual = outcome.friction_residual;
  } else if (solve.problem->has_exact_friction()) {
    auto outcome = solvers::augmented_lagrangian<2>(nonlinear, *solver, case_.solver, {}, times);
    solve.velocity = outcome.solve.velocity;
    solve.stop_reason = outcome.solve.stop_reason;
    solve.iterations = static_cast<int>(outcome.solve.history.size());
    solve.multipliers = outcome.multipliers;
    solve.augmentations = outcome.augmentations;
    solve.multiplier_change = outcome.multiplier_change;
    solve.friction_residual = outcome.friction_residual;
  } else if (newton) {
    auto outcome = solvers::newton_iteration(nonlinear, *solver, case_.solver, {}, times);
    solve.velocity = outcome.velocity;
    solve.stop_reason = outcome.stop_reason;
    solve.iterations = static_cast<int>(outcome.history.size());
  } else {
    auto outcome = solvers::secant_iteration(nonlinear, *solver, case_.solver, {}, times);
    solve.velocity = outcome.velocity;
    solve.stop_reason = outcome.stop_reason;
    solve.iterations = static_cast<int>(outcome.history.size());
  }
  post::evaluate_results<2>(*solve.problem, solve.velocity, solve.results, &solve.multipliers);
  return solve;
}

/// ‖a − b‖/‖b‖ of two full nodal velocity vectors (the relative l² norm of the
/// friction study; every node weighs the same on the uniform meshes used).
inline double relative_velocity_difference(const VectorX& a, const VectorX& b) {
  return (a - b).norm() / b.norm();
}

} // namespace formflow::testing
