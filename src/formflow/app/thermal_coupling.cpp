// SPDX-License-Identifier: MIT
// Hot forming: flow and heat solved in turn until neither changes (issue 18).
#include "formflow/app/thermal_coupling.hpp"

#include "formflow/physics/friction.hpp"
#include "formflow/solvers/linear_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace formflow::app {

template <int dim>
assembly::HeatSources heat_sources(const assembly::FormingProblem<dim>& problem,
                                   const physics::Thermal& thermal, const VectorX& u,
                                   const assembly::FrictionMultipliers<dim>* multipliers) {
  assembly::HeatSources sources;
  sources.deformation = problem.dissipation_density(u);
  for (Real& value : sources.deformation) value *= thermal.taylor_quinney;
  if (!physics::friction_vanishes(problem.settings().friction)) {
    const auto state =
        problem.contact_state(u, problem.has_exact_friction() ? multipliers : nullptr);
    sources.friction.reserve(state.size());
    for (const auto& point : state)
      sources.friction.push_back(thermal.friction_share *
                                 point.friction_traction.dot(point.tangential_velocity));
  }
  return sources;
}

std::vector<Real> law_temperatures(const physics::Thermal& thermal, std::vector<Real> T) {
  Real low = std::min(thermal.billet_temperature, thermal.tool_temperature);
  if (thermal.free_surface_transfer > 0) low = std::min(low, thermal.ambient_temperature);
  for (Real& value : T) value = std::clamp(value, low, thermal.max_temperature);
  return T;
}

namespace {

using Clock = std::chrono::steady_clock;

/// One heat solve at `u`: the nodal T, or nothing when the LU fails or T is not finite.
template <int dim>
std::optional<VectorX> solve_heat(const assembly::HeatProblem<dim>& heat,
                                  const assembly::HeatSources& sources, const VectorX& u,
                                  PhaseTimes& timing) {
  assembly::HeatSystem system;
  {
    ScopedTimer timer(timing, "thermal_assembly");
    system = heat.assemble(u, sources);
  }
  ScopedTimer timer(timing, "thermal_solve");
  // The convection term makes A unsymmetric: LU (UMFPACK), every entry handed over.
  auto solver =
      solvers::make_linear_solver(solvers::LinearSolverKind::Umfpack, solvers::MatrixStorage::Full);
  VectorX free;
  if (!solver->analyze(system.matrix) || !solver->factorize(system.matrix) ||
      !solver->solve(system.rhs, free) || !free.allFinite())
    return std::nullopt;
  return heat.expand(free);
}

Real last_pressure(const solvers::SecantOutcome& outcome) {
  return outcome.history.empty() ? 0.0 : outcome.history.back().pressure;
}

} // namespace

template <int dim>
solvers::SecantOutcome
couple_thermal(const io::Case& case_, assembly::FormingProblem<dim>& problem,
               const FlowSolve& solve_flow, const IterationCallback& on_iteration,
               const assembly::FrictionMultipliers<dim>& multipliers, post::Results& results) {
  const physics::Thermal& thermal = case_.thermal;
  post::ThermalResults& out = results.thermal;
  out.enabled = true;
  assembly::HeatProblem<dim> heat(problem.discretisation(), thermal);
  const int n_points = static_cast<int>(problem.mesh().n_cells()) * problem.full_rule().size();
  // The first flow solve at the billet's temperature everywhere.
  problem.set_point_temperatures(law_temperatures(
      thermal, std::vector<Real>(static_cast<std::size_t>(n_points), thermal.billet_temperature)));
  solvers::SecantOutcome outcome = solve_flow(nullptr);
  out.flow_iterations.push_back(static_cast<int>(outcome.history.size()));
  // history.csv and `iterations` count every flow iteration of every coupling step.
  std::vector<solvers::IterationRecord> history = outcome.history;
  VectorX previous = VectorX::Constant(heat.n_nodes(), thermal.billet_temperature);
  Real previous_pressure = last_pressure(outcome);
  for (int step = 1; step <= thermal.max_coupling_iterations; ++step) {
    if (outcome.stop_reason != solvers::StopReason::Converged) break; // its reason stands
    const auto start = Clock::now();
    const auto sources = heat_sources(problem, thermal, outcome.velocity, &multipliers);
    const std::optional<VectorX> T = solve_heat(heat, sources, outcome.velocity, results.timing);
    if (!T) {
      outcome.stop_reason = solvers::StopReason::SolverFailed;
      break;
    }
    const Real rise = std::max((T->array() - thermal.billet_temperature).abs().maxCoeff(),
                               std::numeric_limits<Real>::min());
    const Real temperature_change = (*T - previous).cwiseAbs().maxCoeff() / rise;
    problem.set_point_temperatures(law_temperatures(thermal, heat.point_values(*T)));
    const VectorX velocity = outcome.velocity;
    outcome = solve_flow(&velocity);
    out.flow_iterations.push_back(static_cast<int>(outcome.history.size()));
    history.insert(history.end(), outcome.history.begin(), outcome.history.end());
    const Real pressure = last_pressure(outcome);
    const Real force_change =
        std::abs(pressure - previous_pressure) / std::max(std::abs(pressure), 1e-300);
    previous = *T;
    previous_pressure = pressure;
    out.coupling_iterations = step;
    out.temperature_change = temperature_change;
    out.force_change = force_change;
    if (on_iteration) {
      solvers::IterationRecord record;
      record.iteration = step;
      record.coupling = step;
      record.relative_change = temperature_change;
      record.force_change = force_change;
      record.pressure = pressure;
      record.max_temperature = T->maxCoeff();
      record.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      on_iteration(record);
    }
    if (outcome.stop_reason != solvers::StopReason::Converged) break;
    if (temperature_change < thermal.coupling_tolerance &&
        force_change < thermal.coupling_tolerance) {
      out.coupling_converged = true;
      break;
    }
  }
  if (outcome.stop_reason == solvers::StopReason::Converged && !out.coupling_converged)
    outcome.stop_reason = solvers::StopReason::MaxIterations;
  outcome.history = std::move(history);
  // What is reported: the heat solve at the final velocity (the flow there was solved
  // at the previous T, within the coupling tolerance of this one).
  const auto sources = heat_sources(problem, thermal, outcome.velocity, &multipliers);
  const std::optional<VectorX> T = solve_heat(heat, sources, outcome.velocity, results.timing);
  if (!T) {
    outcome.stop_reason = solvers::StopReason::SolverFailed;
    out.temperature = previous; // what it has
    return outcome;
  }
  out.temperature = *T;
  out.max_temperature = T->maxCoeff();
  out.min_temperature = T->minCoeff();
  const assembly::HeatBalance balance = heat.balance(outcome.velocity, sources, *T);
  out.deformation = balance.deformation;
  out.friction = balance.friction;
  out.tools = balance.tools;
  out.free_surfaces = balance.free_surfaces;
  out.convected = balance.convected;
  out.conducted = balance.conducted;
  const auto exit = heat.exit_temperature(outcome.velocity, *T);
  out.exit_min = exit.min, out.exit_mean = exit.mean, out.exit_max = exit.max;
  return outcome;
}

template assembly::HeatSources heat_sources<2>(const assembly::FormingProblem<2>&,
                                               const physics::Thermal&, const VectorX&,
                                               const assembly::FrictionMultipliers<2>*);
template assembly::HeatSources heat_sources<3>(const assembly::FormingProblem<3>&,
                                               const physics::Thermal&, const VectorX&,
                                               const assembly::FrictionMultipliers<3>*);
template solvers::SecantOutcome couple_thermal<2>(const io::Case&, assembly::FormingProblem<2>&,
                                                  const FlowSolve&, const IterationCallback&,
                                                  const assembly::FrictionMultipliers<2>&,
                                                  post::Results&);
template solvers::SecantOutcome couple_thermal<3>(const io::Case&, assembly::FormingProblem<3>&,
                                                  const FlowSolve&, const IterationCallback&,
                                                  const assembly::FrictionMultipliers<3>&,
                                                  post::Results&);

} // namespace formflow::app
