// SPDX-License-Identifier: MIT
// One case from parameters to results.
#include "formflow/app/simulation.hpp"

#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/uzawa_iteration.hpp"

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
  return settings;
}

}  // namespace

Simulation simulate(const io::Case& case_, const IterationCallback& on_iteration) {
  Simulation simulation;
  post::Results& results = simulation.results;
  const auto start = std::chrono::steady_clock::now();
  {
    ScopedTimer timer(results.timing, "mesh");
    simulation.mesh = mesh::make_channel_mesh(case_.geometry, case_.mesh_size,
                                              fem::element_order(case_.element));
  }
  std::unique_ptr<assembly::FormingProblem<2>> problem;
  {
    ScopedTimer timer(results.timing, "setup");
    problem = std::make_unique<assembly::FormingProblem<2>>(simulation.mesh, settings_of(case_));
  }
  // Mixed formulation and exact constraints (issue 5): pressures condensed cell
  // by cell keep the velocity system SPD, so CHOLMOD serves every formulation.
  std::unique_ptr<assembly::ConstraintMultipliers<2>> multipliers;
  if (case_.formulation.type == assembly::FormulationType::Mixed || case_.penalty.d_n == 0) {
    multipliers = std::make_unique<assembly::ConstraintMultipliers<2>>(
        simulation.mesh, case_.penalty, case_.formulation, problem->full_rule(),
        problem->n_contact_points());
    problem->attach_multipliers(multipliers.get());
  }
  auto solver = solvers::make_cholmod_solver();
  solvers::SecantOutcome outcome =
      multipliers && multipliers->needs_uzawa()
          ? solvers::uzawa_secant_iteration(*problem, *solver, case_.solver, on_iteration,
                                            results.timing)
          : solvers::secant_iteration(*problem, *solver, case_.solver, on_iteration, results.timing);
  results.stop_reason = outcome.stop_reason;
  results.history = std::move(outcome.history);
  results.iterations = static_cast<int>(results.history.size());
  post::evaluate_results(*problem, outcome.velocity, results);
  results.timing.add("total",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return simulation;
}

}  // namespace formflow::app
