// SPDX-License-Identifier: MIT
// A manufactured-solution case: box mesh, exact boundary values, body force, error norms.
#include "formflow/app/simulation.hpp"

#include "formflow/assembly/boundary_values.hpp"
#include "formflow/core/error.hpp"
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/cube_mesh.hpp"
#include "formflow/physics/manufactured_3d.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <chrono>
#include <memory>
#include <variant>

namespace formflow::app {

namespace {

/// The exact field of `case_` in `dim` dimensions: the stream-function field on the
/// unit square, the vector-potential field on the unit cube.
template <int dim> auto exact_field(const io::Case& case_) {
  if constexpr (dim == 2)
    return physics::StreamFunctionField::of(case_.manufactured);
  else
    return physics::VectorPotentialField::of(case_.manufactured);
}

template <int dim>
void solve_manufactured(const io::Case& case_, Simulation& simulation,
                        const IterationCallback& on_iteration, bool estimate_condition) {
  post::Results& results = simulation.results;
  const mesh::Mesh<dim>& box = std::get<mesh::Mesh<dim>>(simulation.mesh);
  const auto field = exact_field<dim>(case_);
  assembly::ProblemSettings settings = problem_settings(case_);
  // The manufactured fields are Cartesian (physics/manufactured*.hpp); the box has no axis.
  settings.symmetry = physics::Symmetry::Plane;
  auto velocity = [field](const Point<dim>& x) { return field.velocity(x); };
  auto body_force = [field, law = settings.law](const Point<dim>& x) {
    return physics::manufactured_body_force(law, field, x);
  };
  std::unique_ptr<assembly::FormingProblem<dim>> problem;
  {
    ScopedTimer timer(results.timing, "setup");
    problem = std::make_unique<assembly::FormingProblem<dim>>(
        box, settings, assembly::make_boundary_constraints<dim>(box, velocity), body_force);
  }
  auto solver = solvers::make_cholmod_solver();
  solvers::FormingNonlinearProblem<dim> nonlinear(*problem);
  solvers::SecantOutcome outcome =
      solvers::secant_iteration(nonlinear, *solver, case_.solver, on_iteration, results.timing);
  results.stop_reason = outcome.stop_reason;
  results.history = std::move(outcome.history);
  results.iterations = static_cast<int>(results.history.size());
  post::evaluate_results(*problem, outcome.velocity, results);
  simulation.errors = post::error_norms<dim>(
      *problem, outcome.velocity,
      {velocity, [field](const Point<dim>& x) { return field.gradient(x); }});
  if (estimate_condition)
    simulation.reciprocal_condition = condition_at(*problem, outcome.velocity);
}

} // namespace

Simulation simulate_manufactured(const io::Case& case_, const IterationCallback& on_iteration,
                                 bool estimate_condition) {
  Simulation simulation;
  const auto start = std::chrono::steady_clock::now();
  const int cells = mesh::cells_along(1.0, case_.mesh.size);
  FF_ASSERT(cells > 0, "the case validation guarantees that mesh.size divides 1");
  const int order = fem::element_order(case_.element);
  {
    ScopedTimer timer(simulation.results.timing, "mesh");
    if (case_.mesh.dimension == 3)
      simulation.mesh = mesh::make_unit_cube_mesh(cells, order, case_.mesh.distortion);
    else
      simulation.mesh = mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), cells, cells,
                                            order, case_.mesh.distortion);
  }
  if (case_.mesh.dimension == 3)
    solve_manufactured<3>(case_, simulation, on_iteration, estimate_condition);
  else
    solve_manufactured<2>(case_, simulation, on_iteration, estimate_condition);
  simulation.results.timing.add(
      "total", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return simulation;
}

} // namespace formflow::app
