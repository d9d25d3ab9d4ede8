// SPDX-License-Identifier: MIT
// The error estimate's other levels: solved to δ by Newton or by the run's own loop, and
// the case with its regularisations doubled.
#include "formflow/app/estimate_levels.hpp"
#include "formflow/app/thermal_coupling.hpp"
#include "formflow/assembly/heat_problem.hpp"

#include "formflow/physics/friction.hpp"
#include "formflow/post/load_error_estimate.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/newton_iteration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace formflow::app {

namespace {

/// The regularisations the estimate doubles: the penalties d (incompressibility, also
/// the mixed formulation's), d_N (contact) and d_T (friction), and the paper's power
/// law's rate sensitivity α, which makes σ_p = A ε̄̇^α "nearly perfectly plastic"
/// (SPEC §1): its limit α → 0 is the rigid-plastic problem the slip-line referees
/// solve. Other laws' rate dependence is the material's, not doubled.
constexpr std::array<std::string_view, 4> regularisation_keys = {"penalty.d", "penalty.d_n",
                                                                 "friction.d_t", "material.alpha"};

/// Whether `key` (of regularisation_keys) regularises `plan`: α only for the power law.
bool regularises(const RunPlan& plan, std::string_view key) {
  return key != "material.alpha" ||
         std::holds_alternative<physics::PiecewisePower>(plan.problem.law.model);
}

/// `plan` with the regularisation `key` doubled.
RunPlan with_doubled(const RunPlan& plan, std::string_view key) {
  RunPlan doubled = plan;
  if (key == "penalty.d") doubled.problem.penalty.d *= 2;
  if (key == "penalty.d_n") doubled.problem.penalty.d_n *= 2;
  if (key == "friction.d_t") doubled.problem.friction.d_t *= 2;
  if (key == "material.alpha")
    std::get<physics::PiecewisePower>(doubled.problem.law.model).alpha *= 2;
  return doubled;
}

} // namespace

post::LoadErrorEstimate no_estimate(std::string why) {
  post::LoadErrorEstimate estimate;
  estimate.unavailable = std::move(why);
  return estimate;
}

template <int dim>
IterationCallback level_stage(const IterationCallback& on_iteration, std::string_view what,
                              const mesh::Mesh<dim>& mesh) {
  return with_stage(on_iteration,
                    fmt::format("error estimate: {}, {} dofs", what, dim * mesh.n_nodes()));
}

template <int dim>
std::unique_ptr<assembly::ConstraintMultipliers<dim>>
attached_pressure_multipliers(const RunPlan& plan, const mesh::Mesh<dim>& mesh,
                              assembly::FormingProblem<dim>& problem) {
  if (plan.formulation.type != assembly::FormulationType::Mixed) return nullptr;
  auto pressure = std::make_unique<assembly::ConstraintMultipliers<dim>>(
      mesh, plan.problem.penalty, plan.formulation, problem.full_rule(), problem.n_contact_points(),
      problem.discretisation().axisymmetric());
  problem.attach_multipliers(pressure.get());
  return pressure;
}

template <int dim>
std::optional<Real> solved_load(const RunPlan& plan, const mesh::Mesh<dim>& mesh, VectorX start,
                                Index& iterations, const IterationCallback& on_iteration,
                                VectorX* solution) {
  assembly::FormingProblem<dim> problem(mesh, plan.problem);
  const auto pressure = attached_pressure_multipliers(plan, mesh, problem);
  const assembly::ScatterPlan& scatter = problem.plan();
  for (Index dof = 0; dof < scatter.n_dofs(); ++dof)
    if (scatter.free_index(dof) < 0) start[dof] = problem.constraints().values[dof];
  solvers::IterationControl control = plan.solver;
  control.coarse_levels = 0;
  auto solver =
      solvers::make_linear_solver(plan.solve.linear, solvers::MatrixStorage::SymmetricLower);
  solvers::FormingNonlinearProblem<dim> nonlinear(problem);
  PhaseTimes inner; // timed as a whole by the caller ("error estimate")
  const solvers::SecantOutcome outcome =
      solvers::newton_iteration(nonlinear, *solver, control, on_iteration, inner, &start);
  iterations = static_cast<Index>(outcome.history.size());
  if (outcome.stop_reason != solvers::StopReason::Converged) return std::nullopt;
  if (solution) {
    *solution = outcome.velocity;
    problem.discretisation().owned_dofs().replicate(*solution); // ghosted on several ranks
  }
  return post::driven_load(problem, outcome.velocity);
}

template <int dim> mesh::Mesh<dim> channel_at(const RunPlan& plan, Real size) {
  mesh::MeshSpec spec = plan.mesh;
  spec.size = size;
  return std::get<mesh::Mesh<dim>>(plan.make_mesh(spec));
}

template <int dim>
std::optional<SolvedLevel<dim>> solved_level(const RunPlan& plan, mesh::Mesh<dim> mesh,
                                             VectorX start, Index& iterations,
                                             const IterationCallback& on_iteration) {
  SolvedLevel<dim> level;
  level.mesh = std::move(mesh);
  Index its = 0;
  const std::optional<Real> load =
      solved_load(plan, level.mesh, std::move(start), its, on_iteration, &level.velocity);
  iterations += its;
  if (!load) return std::nullopt;
  level.load = *load;
  return level;
}

template <int dim>
std::optional<SolvedLevel<dim>> solved_by_own_loop(const RunPlan& plan, mesh::Mesh<dim> mesh,
                                                   const VectorX& start, Index& iterations,
                                                   const IterationCallback& on_iteration) {
  RunPlan level_plan = plan;
  level_plan.solver.load_error = solvers::LoadErrorMethod::None; // no estimate of its own
  Simulation simulation = simulate_from<dim>(level_plan, std::move(mesh), start, on_iteration);
  iterations += simulation.results.iterations;
  if (!simulation.results.converged()) return std::nullopt;
  SolvedLevel<dim> level;
  level.mesh = std::move(std::get<mesh::Mesh<dim>>(simulation.mesh));
  level.load = simulation.results.pressure.ram_reaction;
  level.velocity = std::move(simulation.results.fields.velocity);
  if (simulation.results.thermal.enabled)
    level.temperature = std::move(simulation.results.thermal.temperature);
  return level;
}

template <int dim>
void set_level_temperature(const RunPlan& plan, assembly::FormingProblem<dim>& problem,
                           const VectorX& T) {
  const assembly::HeatProblem<dim> heat(problem.discretisation(), plan.thermal);
  problem.set_point_temperatures(law_temperatures(plan.thermal, heat.point_values(T)));
  if (physics::needs_shear_yield(plan.problem.friction))
    problem.set_contact_temperatures(law_temperatures(plan.thermal, heat.contact_values(T)));
}

RunPlan doubled_regularisations(const RunPlan& plan) {
  RunPlan doubled = plan;
  for (std::string_view key : regularisation_keys)
    if (regularises(plan, key)) doubled = with_doubled(doubled, key);
  return doubled;
}

template <int dim>
std::vector<std::pair<std::string, Real>> regularisation_offsets(const RunPlan& plan,
                                                                 const mesh::Mesh<dim>& mesh,
                                                                 const VectorX& u, Real load) {
  std::vector<std::pair<std::string, Real>> offsets;
  for (std::string_view key : regularisation_keys) {
    // d_T regularises nothing without friction.
    if (!regularises(plan, key) ||
        (key == "friction.d_t" && physics::friction_vanishes(plan.problem.friction)))
      continue;
    Index iterations = 0;
    if (const std::optional<Real> doubled =
            solved_load(with_doubled(plan, key), mesh, u, iterations, IterationCallback{}))
      offsets.emplace_back(std::string(key), *doubled - load);
  }
  std::stable_sort(offsets.begin(), offsets.end(), [](const auto& a, const auto& b) {
    return std::abs(a.second) > std::abs(b.second);
  });
  return offsets;
}

template IterationCallback level_stage<2>(const IterationCallback&, std::string_view,
                                          const mesh::Mesh<2>&);
template std::unique_ptr<assembly::ConstraintMultipliers<2>>
attached_pressure_multipliers<2>(const RunPlan&, const mesh::Mesh<2>&,
                                 assembly::FormingProblem<2>&);
template std::optional<Real> solved_load<2>(const RunPlan&, const mesh::Mesh<2>&, VectorX, Index&,
                                            const IterationCallback&, VectorX*);
template mesh::Mesh<2> channel_at<2>(const RunPlan&, Real);
template void set_level_temperature<2>(const RunPlan&, assembly::FormingProblem<2>&,
                                       const VectorX&);
template std::optional<SolvedLevel<2>> solved_level<2>(const RunPlan&, mesh::Mesh<2>, VectorX,
                                                       Index&, const IterationCallback&);
template std::optional<SolvedLevel<2>> solved_by_own_loop<2>(const RunPlan&, mesh::Mesh<2>,
                                                             const VectorX&, Index&,
                                                             const IterationCallback&);
template std::vector<std::pair<std::string, Real>>
regularisation_offsets<2>(const RunPlan&, const mesh::Mesh<2>&, const VectorX&, Real);
template IterationCallback level_stage<3>(const IterationCallback&, std::string_view,
                                          const mesh::Mesh<3>&);
template std::unique_ptr<assembly::ConstraintMultipliers<3>>
attached_pressure_multipliers<3>(const RunPlan&, const mesh::Mesh<3>&,
                                 assembly::FormingProblem<3>&);
template std::optional<Real> solved_load<3>(const RunPlan&, const mesh::Mesh<3>&, VectorX, Index&,
                                            const IterationCallback&, VectorX*);
template mesh::Mesh<3> channel_at<3>(const RunPlan&, Real);
template void set_level_temperature<3>(const RunPlan&, assembly::FormingProblem<3>&,
                                       const VectorX&);
template std::optional<SolvedLevel<3>> solved_level<3>(const RunPlan&, mesh::Mesh<3>, VectorX,
                                                       Index&, const IterationCallback&);
template std::optional<SolvedLevel<3>> solved_by_own_loop<3>(const RunPlan&, mesh::Mesh<3>,
                                                             const VectorX&, Index&,
                                                             const IterationCallback&);
template std::vector<std::pair<std::string, Real>>
regularisation_offsets<3>(const RunPlan&, const mesh::Mesh<3>&, const VectorX&, Real);

} // namespace formflow::app
