// SPDX-License-Identifier: MIT
// A manufactured-solution case: box mesh, exact boundary values, body force, error norms.
#include "formflow/app/simulation.hpp"

#include "formflow/assembly/boundary_values.hpp"
#include "formflow/core/error.hpp"
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <chrono>

namespace formflow::app {

Simulation simulate_manufactured(const io::Case& case_, const IterationCallback& on_iteration,
                                 bool estimate_condition) {
  Simulation simulation;
  post::Results& results = simulation.results;
  const auto start = std::chrono::steady_clock::now();
  const int cells = mesh::cells_along(1.0, case_.mesh.size);
  FF_ASSERT(cells > 0, "the case validation guarantees that mesh.size divides 1");
  {
    ScopedTimer timer(results.timing, "mesh");
    simulation.mesh = mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), cells, cells,
                                          fem::element_order(case_.element), case_.mesh.distortion);
  }
  // The manufactured fields are plane (physics/manufactured.hpp): a 2D run.
  const mesh::Mesh<2>& box = simulation.plane_mesh();
  const physics::StreamFunctionField field = physics::StreamFunctionField::of(case_.manufactured);
  assembly::ProblemSettings settings = problem_settings(case_);
  // The manufactured fields are plane (physics/manufactured.hpp); the box has no axis.
  settings.symmetry = physics::Symmetry::Plane;
  auto velocity = [field](const Point<2>& x) { return field.velocity(x); };
  auto body_force = [field, law = settings.law](const Point<2>& x) {
    return physics::manufactured_body_force(law, field, x);
  };
  std::unique_ptr<assembly::FormingProblem<2>> problem;
  {
    ScopedTimer timer(results.timing, "setup");
    problem = std::make_unique<assembly::FormingProblem<2>>(
        box, settings, assembly::make_boundary_constraints<2>(box, velocity), body_force);
  }
  auto solver = solvers::make_cholmod_solver();
  solvers::FormingNonlinearProblem<2> nonlinear(*problem);
  solvers::SecantOutcome outcome =
      solvers::secant_iteration(nonlinear, *solver, case_.solver, on_iteration, results.timing);
  results.stop_reason = outcome.stop_reason;
  results.history = std::move(outcome.history);
  results.iterations = static_cast<int>(results.history.size());
  post::evaluate_results(*problem, outcome.velocity, results);
  simulation.errors =
      post::error_norms<2>(*problem, outcome.velocity,
                           {velocity, [field](const Point<2>& x) { return field.gradient(x); }});
  if (estimate_condition)
    simulation.reciprocal_condition = condition_at(*problem, outcome.velocity);
  results.timing.add(
      "total", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return simulation;
}

} // namespace formflow::app
