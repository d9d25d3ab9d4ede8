// SPDX-License-Identifier: MIT
// The solve plan of a case, from the capability table.
#include "formflow/app/solve_plan.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/problem_shape.hpp"

namespace formflow::app {

SolvePlan make_solve_plan(const io::Case& case_) {
  SolvePlan plan;
  plan.shape = io::problem_shape(case_);
  const auto choice = solvers::choose_loop(plan.shape);
  FF_ASSERT(std::holds_alternative<solvers::LoopKind>(choice),
            "load_case refuses the combinations no loop serves");
  plan.loop = std::holds_alternative<solvers::LoopKind>(choice)
                  ? std::get<solvers::LoopKind>(choice)
                  : solvers::LoopKind::Secant;
  plan.linear = solvers::linear_solver_for(plan.loop, plan.shape);
  plan.coarse_levels = plan.sequences_meshes() ? case_.solver.coarse_levels : 0;
  plan.friction_augmentation = plan.loop == solvers::LoopKind::AugmentedNewton
                                   ? case_.friction.newton_augmentation
                                   : case_.friction.augmentation;
  // Exact stick: r only predicts the active set (|λ̂ + r u_T| ≤ τ_f) and no longer holds
  // stuck points, so the stiff 100/d_N the penalty needed is not wanted: with it a slip
  // of 1e-8 flips a point, and one grid case cycled at δ = 1e-8 (axisymmetric Q2,
  // sliding, h = 0.5, μ = 0.3: stalled after 20; with 1/d_N converged in 15). Unless
  // friction.newton_augmentation is given, r = 1/d_N (docs/friction.md "Session 8").
  if (plan.shape.exact_stick && !case_.key_locations.count("friction.newton_augmentation"))
    plan.friction_augmentation = 1.0;
  return plan;
}

std::string SolvePlan::name(bool coarse_start_ran) const {
  std::string text = solvers::loop_name(loop, shape);
  if (coarse_start_ran) text += " from coarse meshes";
  return text;
}

} // namespace formflow::app
