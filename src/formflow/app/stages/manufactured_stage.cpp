// SPDX-License-Identifier: MIT
// A manufactured-solution case: box mesh, exact boundary values, body force, error norms.
#include "formflow/app/manufactured_mesh.hpp"
#include "formflow/app/stages/stage.hpp"
#include "formflow/app/thermal_coupling.hpp"

#include "formflow/assembly/boundary_values.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/element_choice.hpp"
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/cube_mesh.hpp"
#include "formflow/mesh/simplex_split.hpp"
#include "formflow/mesh/tetrahedral_split.hpp"
#include "formflow/physics/manufactured_3d.hpp"
#include "formflow/physics/manufactured_thermal.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/pattern_reuse.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <chrono>
#include <memory>
#include <variant>

namespace formflow::app {

namespace {

/// The coupled solution's T: from the billet's temperature up to 1.5 × the rise above it.
physics::ManufacturedTemperature manufactured_temperature(const physics::Thermal& thermal) {
  return physics::ManufacturedTemperature(thermal.billet_temperature,
                                          physics::coupled_temperature_rise);
}

/// The exact field of `plan` in `dim` dimensions: the stream-function field on the
/// unit square, the vector-potential field on the unit cube.
template <int dim> auto exact_field(const RunPlan& plan) {
  if constexpr (dim == 2)
    return physics::StreamFunctionField::of(plan.manufactured);
  else
    return physics::VectorPotentialField::of(plan.manufactured);
}

/// The coupled manufactured solution (thermal.enabled, plane only): the smooth velocity
/// with the temperature of physics/manufactured_thermal.hpp, solved by the staggered loop
/// of a hot run (app/thermal_coupling.hpp) with the exact T on all of ∂Ω, the body force
/// of the temperature-dependent law and the heat source that make the pair exact. The
/// velocity of the convection and the β σ_p ε̄̇ of the heat source are the discrete ones.
void solve_coupled_manufactured(const RunPlan& plan, Simulation& simulation,
                                const IterationCallback& on_iteration) {
  post::Results& results = simulation.results;
  const mesh::Mesh<2>& box = std::get<mesh::Mesh<2>>(simulation.mesh);
  const auto field = physics::StreamFunctionField::of(plan.manufactured);
  const physics::ManufacturedTemperature temperature = manufactured_temperature(plan.thermal);
  assembly::ProblemSettings settings = plan.problem;
  settings.symmetry = physics::Symmetry::Plane;
  const physics::FlowLaw law = plan.problem.law; // its T is set at each point
  auto velocity = [field](const Point<2>& x) { return field.velocity(x); };
  auto body_force = [field, temperature, law](const Point<2>& x) {
    return physics::coupled_body_force(law, field, temperature, x);
  };
  std::unique_ptr<assembly::FormingProblem<2>> problem;
  {
    ScopedTimer timer(results.timing, "setup");
    problem = std::make_unique<assembly::FormingProblem<2>>(
        box, settings, assembly::make_boundary_constraints<2>(box, velocity), body_force);
  }
  // The heat source at the full-rule points, in the cell-major order of the sources.
  ManufacturedHeat<2> heat;
  heat.temperature = [temperature](const Point<2>& x) { return temperature.value(x); };
  {
    const auto& discretisation = problem->discretisation();
    fem::CellValues<2> values(box.cell_type(), discretisation.full_rule());
    typename fem::CellValues<2>::Gradients coordinates, unused;
    for (Index cell = 0; cell < box.n_cells(); ++cell) {
      discretisation.gather(cell, nullptr, coordinates, unused);
      values.reinit(coordinates);
      for (int q = 0; q < values.n_points(); ++q)
        heat.source.push_back(
            physics::coupled_heat_source(law, plan.thermal, field, temperature, values.point(q)));
    }
  }
  // The body force rules Newton out (assembly/newton_system.cpp): the secant loop, from
  // its own start at each coupling step, one CHOLMOD analysis for all of them.
  const auto solver = solvers::reuse_analysis(solvers::make_cholmod_solver());
  const FlowSolve solve_flow = [&](const VectorX*, Real tolerance) {
    solvers::FormingNonlinearProblem<2> nonlinear(*problem);
    solvers::IterationControl control = plan.solver;
    control.tolerance = tolerance;
    return solvers::secant_iteration(nonlinear, *solver, control, on_iteration, results.timing);
  };
  const assembly::FrictionMultipliers<2> no_multipliers;
  solvers::SecantOutcome outcome =
      couple_thermal(plan.thermal, plan.problem.friction, plan.solver.tolerance, *problem,
                     solve_flow, on_iteration, no_multipliers, results, &heat);
  results.stop_reason = outcome.stop_reason;
  results.history = std::move(outcome.history);
  results.iterations = static_cast<int>(results.history.size());
  post::evaluate_results(*problem, outcome.velocity, results);
  results.fields.temperature = results.thermal.temperature;
  simulation.errors =
      post::error_norms<2>(*problem, outcome.velocity,
                           {velocity, [field](const Point<2>& x) { return field.gradient(x); }});
  simulation.temperature_errors = post::temperature_error_norms<2>(
      problem->discretisation(), results.thermal.temperature,
      {[temperature](const Point<2>& x) { return temperature.value(x); },
       [temperature](const Point<2>& x) { return temperature.gradient(x); }});
}

template <int dim>
void solve_manufactured(const RunPlan& plan, Simulation& simulation,
                        const IterationCallback& on_iteration, bool estimate_condition) {
  post::Results& results = simulation.results;
  const mesh::Mesh<dim>& box = std::get<mesh::Mesh<dim>>(simulation.mesh);
  const auto field = exact_field<dim>(plan);
  assembly::ProblemSettings settings = plan.problem;
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
  // The mixed formulation (the only one of triangles) with its pressure condensed per cell:
  // the velocity system stays SPD for CHOLMOD (case validation: d > 0, condensed).
  std::unique_ptr<assembly::ConstraintMultipliers<dim>> pressure;
  if (plan.formulation.type == assembly::FormulationType::Mixed) {
    pressure = std::make_unique<assembly::ConstraintMultipliers<dim>>(
        box, settings.penalty, plan.formulation, problem->full_rule(), problem->n_contact_points());
    problem->attach_multipliers(pressure.get());
  }
  auto solver = solvers::make_cholmod_solver();
  solvers::FormingNonlinearProblem<dim> nonlinear(*problem);
  solvers::SecantOutcome outcome =
      solvers::secant_iteration(nonlinear, *solver, plan.solver, on_iteration, results.timing);
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

mesh::AnyMesh manufactured_mesh(const RunPlan& plan) {
  const int cells = mesh::cells_along(1.0, plan.mesh.size);
  FF_ASSERT(cells > 0, "the case validation guarantees that mesh.size divides 1");
  const int order = fem::element_order(plan.element);
  // Simplices: each (distorted) square cut along its diagonal, each cube into six
  // tetrahedra around its main diagonal.
  const mesh::CellType type =
      fem::velocity_cell_type(plan.element, plan.formulation.pressure,
                              plan.formulation.type == assembly::FormulationType::Mixed);
  if (plan.mesh.dimension == 3) {
    mesh::Mesh<3> cube = mesh::make_unit_cube_mesh(cells, order, plan.mesh.distortion);
    if (type.is_simplex()) return mesh::split_into_tetrahedra(cube, type.bubbles);
    return cube;
  }
  const mesh::Mesh<2> box = mesh::make_box_mesh(Point<2>(0.0, 0.0), Point<2>(1.0, 1.0), cells,
                                                cells, order, plan.mesh.distortion);
  if (type.is_simplex()) return mesh::split_into_triangles(box, type.bubbles);
  return box;
}

namespace {

/// A manufactured solution (verification.solution ≠ none) on the unit box the run made
/// (manufactured_mesh): the exact velocity on the whole boundary, its body force, the
/// secant loop; with thermal.enabled the coupled pair by the hot run's staggered loop.
/// A solve stage of its own, the only stage of its chain: its stop rule is the loop's
/// (and the coupling's); its block in summary.json the error norms (`errors`).
class ManufacturedStage final : public StageOf<ManufacturedStage> {
public:
  std::string_view name() const override { return "manufactured solution"; }

  template <int dim> void run_on(SolveState<dim>& state, const StageChain&) const {
    const RunPlan& plan = state.run_plan();
    if constexpr (dim == 2) {
      if (plan.thermal.enabled) { // plane only (case validation)
        solve_coupled_manufactured(plan, *state.simulation, state.on_iteration);
        return;
      }
    }
    solve_manufactured<dim>(plan, *state.simulation, state.on_iteration, state.estimate_condition);
  }
};

} // namespace

const Stage& manufactured_stage() {
  static const ManufacturedStage stage;
  return stage;
}

} // namespace formflow::app
