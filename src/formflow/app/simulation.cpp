// SPDX-License-Identifier: MIT
// One case from parameters to results.
#include "formflow/app/simulation.hpp"
#include "formflow/app/coarse_start.hpp"
#include "formflow/app/solve_plan.hpp"

#include "formflow/io/mesh_input.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/augmented_lagrangian.hpp"
#include "formflow/solvers/augmented_newton.hpp"
#include "formflow/solvers/condition_estimate.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/newton_iteration.hpp"
#include "formflow/solvers/saddle_point_iteration.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <chrono>

namespace formflow::app {

assembly::ProblemSettings problem_settings(const io::Case& case_) {
  assembly::ProblemSettings settings;
  settings.process = case_.process;
  settings.law = case_.material.selected();
  settings.viscous_strain = case_.viscous_strain;
  settings.penalty = case_.penalty;
  settings.friction = case_.friction;
  // The augmentation of the loop that runs (friction.newton_augmentation for Newton's).
  settings.friction.augmentation = make_solve_plan(case_).friction_augmentation;
  settings.volumetric_points = case_.volumetric_points;
  settings.initial_rate = case_.solver.initial_rate;
  settings.symmetry = case_.symmetry;
  settings.contact = case_.contact;
  return settings;
}

Real condition_at(const assembly::FormingProblem<2>& problem, const VectorX& u) {
  assembly::LinearSystem system = problem.plan().make_system();
  problem.assemble(&u, system);
  return solvers::reciprocal_condition_estimate(system.matrix);
}

Simulation simulate(const io::Case& case_, const IterationCallback& on_iteration,
                    bool estimate_condition) {
  if (case_.manufactured != physics::ManufacturedSolution::None)
    return simulate_manufactured(case_, on_iteration, estimate_condition);
  Simulation simulation;
  post::Results& results = simulation.results;
  const auto start = std::chrono::steady_clock::now();
  {
    ScopedTimer timer(results.timing, "mesh");
    simulation.mesh = io::load_mesh(case_);
  }
  std::unique_ptr<assembly::FormingProblem<2>> problem;
  {
    ScopedTimer timer(results.timing, "setup");
    problem =
        std::make_unique<assembly::FormingProblem<2>>(simulation.mesh, problem_settings(case_));
  }
  // Mixed formulation and exact constraints (issue 5): pressures condensed cell
  // by cell keep the velocity system SPD, so CHOLMOD serves every formulation.
  // Exact friction (friction.regularization = "none") with d = 0 or d_N = 0 is
  // refused by the case validation: one multiplier loop at a time.
  std::unique_ptr<assembly::ConstraintMultipliers<2>> constraint_multipliers;
  if (case_.formulation.type == assembly::FormulationType::Mixed || case_.penalty.d_n == 0) {
    constraint_multipliers = std::make_unique<assembly::ConstraintMultipliers<2>>(
        simulation.mesh, case_.penalty, case_.formulation, problem->full_rule(),
        problem->n_contact_points());
    problem->attach_multipliers(constraint_multipliers.get());
  }
  const SolvePlan plan = make_solve_plan(case_);
  auto solver = solvers::make_linear_solver(plan.linear, solvers::loop_storage(plan.loop));
  solvers::SecantOutcome outcome;
  assembly::FrictionMultipliers<2> multipliers;
  // Mesh sequencing (solver.coarse_levels) for the Newton loops: start from the coarse
  // solution. Exact friction's coarse levels solve the Coulomb law with λ̂ = 0, i.e.
  // stick penalty r (the multipliers live at the fine Γ3 points only).
  std::optional<CoarseStart> coarse;
  if (plan.is_newton()) {
    coarse = coarse_start(case_, simulation.mesh, results.timing);
    if (coarse) {
      results.coarse_iterations = coarse->iterations;
      results.coarse_mesh_sizes = coarse->mesh_sizes;
    }
  }
  const VectorX* start_velocity = coarse ? &coarse->velocity : nullptr;
  // Each loop is a driver (secant or Newton) over the problem's nonlinear
  // interface, its linear step swapped (Uzawa steps, the saddle point) or the
  // whole driver wrapped by exact friction's augmentation.
  solvers::FormingNonlinearProblem<2> nonlinear(*problem);
  solvers::TimedLinearStep linear(*solver, results.timing);
  const auto take_augmented = [&](solvers::AugmentedOutcome<2>&& augmented) {
    outcome = std::move(augmented.solve);
    multipliers = std::move(augmented.multipliers);
    results.augmentation = {augmented.augmentations, augmented.multiplier_change};
  };
  switch (plan.loop) {
  case solvers::LoopKind::AugmentedNewton:
    // Exact Coulomb friction by Newton, multipliers updated between its steps
    // (solvers/augmented_newton.hpp).
    take_augmented(solvers::augmented_newton(nonlinear, *solver, case_.solver, on_iteration,
                                             results.timing, start_velocity));
    break;
  case solvers::LoopKind::AugmentedSecant:
    // Exact friction, the paper's method (or a mixed formulation): the
    // augmentation around the secant iteration, an update per converged inner solve.
    take_augmented(solvers::augmented_lagrangian(nonlinear, *solver, case_.solver, on_iteration,
                                                 results.timing));
    break;
  case solvers::LoopKind::SaddlePointSecant: {
    // Taylor–Hood: a continuous pressure cannot be condensed; the saddle-point
    // system is indefinite (an LU back-end, solvers/capabilities.hpp).
    solvers::SaddlePointSolve<2> saddle(nonlinear, linear);
    outcome = solvers::secant_iteration(nonlinear, saddle, case_.solver, on_iteration);
    break;
  }
  case solvers::LoopKind::UzawaSecant: {
    solvers::SecantSolve uzawa(nonlinear, linear, /*uzawa_steps=*/true);
    outcome = solvers::secant_iteration(nonlinear, uzawa, case_.solver, on_iteration);
    break;
  }
  case solvers::LoopKind::Newton:
    // The penalty problem (plane and axisymmetric) and the mixed one with its
    // pressure condensed at d > 0 (the condensation is linear in u).
    outcome = solvers::newton_iteration(nonlinear, *solver, case_.solver, on_iteration,
                                        results.timing, start_velocity);
    break;
  case solvers::LoopKind::Secant:
    outcome =
        solvers::secant_iteration(nonlinear, *solver, case_.solver, on_iteration, results.timing);
    break;
  }
  results.method = plan.name(coarse.has_value());
  results.stop_reason = outcome.stop_reason;
  results.history = std::move(outcome.history);
  results.iterations = static_cast<int>(results.history.size());
  post::evaluate_results(*problem, outcome.velocity, results, &multipliers);
  if (estimate_condition)
    simulation.reciprocal_condition = condition_at(*problem, outcome.velocity);
  results.timing.add(
      "total", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return simulation;
}

} // namespace formflow::app
