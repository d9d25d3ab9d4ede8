// SPDX-License-Identifier: MIT
// A run of a plan: its mesh, then the stages composed around the solve (app/run.hpp).
#include "formflow/app/run.hpp"

#include "formflow/app/manufactured_mesh.hpp"
#include "formflow/app/stages/composition.hpp"
#include "formflow/app/stages/stage.hpp"
#include "formflow/solvers/condition_estimate.hpp"

#include <chrono>
#include <variant>

namespace formflow::app {

template <int dim>
Real condition_at(const assembly::FormingProblem<dim>& problem, const VectorX& u) {
  assembly::LinearSystem system = problem.plan().make_system();
  problem.assemble(&u, system);
  return solvers::reciprocal_condition_estimate(system.matrix);
}

namespace {

using Clock = std::chrono::steady_clock;

/// The stages on `simulation`'s mesh, in its dimension, with an input error found by a
/// back-end during the solve (a PETSc option that nothing read: the solver knows the key,
/// not the file) located where the case set that key.
void run_stages(const RunPlan& plan, const std::vector<const Stage*>& stages,
                Simulation& simulation, bool mesh_from_plan, const VectorX* start,
                const IterationCallback& on_iteration, bool estimate_condition) {
  try {
    std::visit(
        [&](const auto& mesh) {
          constexpr int dim = std::decay_t<decltype(mesh)>::dimension;
          SolveState<dim> state;
          state.plan = &plan;
          state.simulation = &simulation;
          state.mesh_from_plan = mesh_from_plan;
          state.start = start;
          state.on_iteration = on_iteration;
          state.estimate_condition = estimate_condition;
          state.control = plan.solver;
          StageChain(stages).run(state);
        },
        simulation.mesh);
  } catch (const InputError& error) {
    if (!error.file.empty()) throw;
    throw plan.keys.error(error.key, error.message, error.hint);
  }
}

void add_total(post::Results& results, Clock::time_point start) {
  results.timing.add("total", std::chrono::duration<double>(Clock::now() - start).count());
}

} // namespace

IterationCallback with_stage(const IterationCallback& on_iteration, std::string stage) {
  if (!on_iteration) return {};
  return [on_iteration, stage = std::move(stage)](const solvers::IterationRecord& record) {
    solvers::IterationRecord staged = record;
    // A stage inside a stage (an adaptive cycle's error estimate) names both.
    staged.stage = record.stage.empty() ? stage : stage + " · " + record.stage;
    on_iteration(staged);
  };
}

Simulation simulate(const RunPlan& plan, const IterationCallback& on_iteration,
                    bool estimate_condition) {
  // What does not compose is refused before anything is made: exit 2.
  const std::vector<const Stage*> stages = compose_stages(plan, MeshOwnership::PlanMeshes);
  Simulation simulation;
  const auto start = Clock::now();
  {
    ScopedTimer timer(simulation.results.timing, "mesh");
    simulation.mesh = plan.is_manufactured() ? manufactured_mesh(plan) : plan.make_mesh(plan.mesh);
  }
  // The one dispatch on the dimension: the mesh source decided it.
  run_stages(plan, stages, simulation, true, nullptr, on_iteration, estimate_condition);
  add_total(simulation.results, start);
  return simulation;
}

template <int dim>
Simulation simulate_on(const RunPlan& plan, mesh::Mesh<dim> mesh,
                       const IterationCallback& on_iteration, bool estimate_condition) {
  const std::vector<const Stage*> stages = compose_stages(plan, MeshOwnership::GivenMesh);
  Simulation simulation;
  const auto start = Clock::now();
  simulation.mesh = std::move(mesh);
  // No mesh sequencing: its coarse levels would be re-made from plan.mesh, which is not
  // where this mesh came from.
  run_stages(plan, stages, simulation, false, nullptr, on_iteration, estimate_condition);
  add_total(simulation.results, start);
  return simulation;
}

template <int dim>
Simulation simulate_from(const RunPlan& plan, mesh::Mesh<dim> mesh, const VectorX& start,
                         const IterationCallback& on_iteration) {
  const std::vector<const Stage*> stages = compose_stages(plan, MeshOwnership::GivenMesh);
  Simulation simulation;
  const auto clock_start = Clock::now();
  simulation.mesh = std::move(mesh);
  run_stages(plan, stages, simulation, false, &start, on_iteration, false);
  add_total(simulation.results, clock_start);
  return simulation;
}

template Simulation simulate_from<2>(const RunPlan&, mesh::Mesh<2>, const VectorX&,
                                     const IterationCallback&);
template Simulation simulate_from<3>(const RunPlan&, mesh::Mesh<3>, const VectorX&,
                                     const IterationCallback&);
template Real condition_at<2>(const assembly::FormingProblem<2>&, const VectorX&);
template Real condition_at<3>(const assembly::FormingProblem<3>&, const VectorX&);
template Simulation simulate_on<2>(const RunPlan&, mesh::Mesh<2>, const IterationCallback&, bool);
template Simulation simulate_on<3>(const RunPlan&, mesh::Mesh<3>, const IterationCallback&, bool);

} // namespace formflow::app
