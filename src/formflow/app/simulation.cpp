// SPDX-License-Identifier: MIT
// One case from parameters to results.
#include "formflow/app/simulation.hpp"

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/augmented_lagrangian.hpp"
#include "formflow/solvers/condition_estimate.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <chrono>

namespace formflow::app {

namespace {

assembly::ProblemSettings settings_of(const io::Case& case_) {
  assembly::ProblemSettings settings;
  settings.process = case_.process;
  settings.law = case_.material;
  settings.viscous_strain = case_.viscous_strain;
  settings.penalty = case_.penalty;
  settings.friction = case_.friction;
  settings.volumetric_points = case_.volumetric_points;
  settings.initial_rate = case_.solver.initial_rate;
  settings.symmetry = case_.symmetry;
  return settings;
}

}  // namespace

assembly::ProblemSettings problem_settings(const io::Case& case_) { return settings_of(case_); }

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
    simulation.mesh = mesh::make_die_channel_mesh(case_.geometry, case_.mesh_size,
                                                  fem::element_order(case_.element));
    if (case_.process.type == physics::ProcessType::Drawing) mesh::free_container_wall(simulation.mesh);
  }
  std::unique_ptr<assembly::FormingProblem<2>> problem;
  {
    ScopedTimer timer(results.timing, "setup");
    problem = std::make_unique<assembly::FormingProblem<2>>(simulation.mesh, settings_of(case_));
  }
  auto solver = solvers::make_cholmod_solver();
  solvers::SecantOutcome outcome;
  assembly::FrictionMultipliers<2> multipliers;
  if (problem->has_exact_friction()) {
    auto augmented = solvers::augmented_lagrangian(
        *problem, solvers::secant_inner_solve(*problem, *solver, results.timing), case_.solver,
        on_iteration);
    outcome = std::move(augmented.solve);
    multipliers = std::move(augmented.multipliers);
    results.augmentation = {augmented.augmentations, augmented.multiplier_change};
  } else {
    outcome =
        solvers::secant_iteration(*problem, *solver, case_.solver, on_iteration, results.timing);
  }
  results.stop_reason = outcome.stop_reason;
  results.history = std::move(outcome.history);
  results.iterations = static_cast<int>(results.history.size());
  post::evaluate_results(*problem, outcome.velocity, results, &multipliers);
  if (estimate_condition) simulation.reciprocal_condition = condition_at(*problem, outcome.velocity);
  results.timing.add("total",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return simulation;
}

}  // namespace formflow::app
