// SPDX-License-Identifier: MIT
// Hot forming: flow and heat solved in turn until neither changes (issue 18).
#include "formflow/app/thermal_coupling.hpp"

#include "formflow/physics/friction.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/pattern_reuse.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <span>

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

/// The loosest inner tolerance of inexact staggering (the first flow solve's): the
/// velocity at the billet's T is only a start for the next step's T.
constexpr Real first_flow_tolerance = 1e-2;

/// One heat solve at `u` with `solver` (its analysis kept from the last solve: the
/// pattern is the mesh's): the nodal T, or nothing when the LU fails or T is not finite.
template <int dim>
std::optional<VectorX> solve_heat(const assembly::HeatProblem<dim>& heat,
                                  const assembly::HeatSources& sources, const VectorX& u,
                                  solvers::LinearSolver& solver, PhaseTimes& timing) {
  assembly::HeatSystem system;
  {
    ScopedTimer timer(timing, "thermal_assembly");
    system = heat.assemble(u, sources);
  }
  ScopedTimer timer(timing, "thermal_solve");
  VectorX free;
  if (!solver.analyze(system.matrix) || !solver.factorize(system.matrix) ||
      !solver.solve(system.rhs, free) || !free.allFinite())
    return std::nullopt;
  return heat.expand(free);
}

/// A distributed run (issue 20, docs/thermal.md): the heat problem is a scalar per node,
/// small beside the flow, and is solved on rank 0 alone (every rank holds the whole
/// velocity after each flow solve); its T, or its failure, goes to every rank, so that
/// the coupling's decisions are the same on all of them. One rank: `solve` itself.
std::optional<VectorX> heat_on_rank_zero(const assembly::Distribution& distribution, Index n_nodes,
                                         const std::function<std::optional<VectorX>()>& solve) {
  if (!distribution.distributed()) return solve();
  VectorX message = VectorX::Zero(n_nodes + 1); // [solved, T]
  if (distribution.rank == 0)
    if (const std::optional<VectorX> T = solve()) {
      message[0] = 1.0;
      message.tail(n_nodes) = *T;
    }
  distribution.sum_over_ranks(std::span<Real>(message.data(), message.size()));
  if (message[0] != 1.0) return std::nullopt;
  return VectorX(message.tail(n_nodes));
}

Real last_pressure(const solvers::SecantOutcome& outcome) {
  return outcome.history.empty() ? 0.0 : outcome.history.back().pressure;
}

} // namespace

template <int dim>
solvers::SecantOutcome
couple_thermal(const physics::Thermal& thermal, const physics::Friction& friction,
               Real final_tolerance, assembly::FormingProblem<dim>& problem,
               const FlowSolve& solve_flow, const IterationCallback& on_iteration,
               const assembly::FrictionMultipliers<dim>& multipliers, post::Results& results,
               const ManufacturedHeat<dim>* manufactured) {
  post::ThermalResults& out = results.thermal;
  out.enabled = true;
  assembly::HeatProblem<dim> heat(problem.discretisation(), thermal,
                                  manufactured
                                      ? manufactured->temperature
                                      : typename assembly::HeatProblem<dim>::BoundaryTemperature{});
  // The sources at `u`, with a manufactured solution's own added.
  const auto sources_at = [&](const VectorX& u) {
    assembly::HeatSources sources = heat_sources(problem, thermal, u, &multipliers);
    if (manufactured)
      for (std::size_t k = 0; k < sources.deformation.size(); ++k)
        sources.deformation[k] += manufactured->source[k];
    return sources;
  };
  // The convection term makes A unsymmetric: LU (UMFPACK), every entry handed over.
  const auto heat_solver = solvers::reuse_analysis(solvers::make_linear_solver(
      solvers::LinearSolverKind::Umfpack, solvers::MatrixStorage::Full));
  const int n_points = static_cast<int>(problem.mesh().n_cells()) * problem.full_rule().size();
  const auto heat_at = [&](const VectorX& u) {
    const assembly::HeatSources sources = sources_at(u); // collective (the contact state)
    return heat_on_rank_zero(problem.discretisation().distribution(), heat.n_nodes(), [&] {
      return solve_heat(heat, sources, u, *heat_solver, results.timing);
    });
  };
  // The first flow solve at the billet's temperature everywhere.
  problem.set_point_temperatures(law_temperatures(
      thermal, std::vector<Real>(static_cast<std::size_t>(n_points), thermal.billet_temperature)));
  // The Γ3 points' T for the Tresca and hybrid shear yield (Coulomb does not read it).
  const bool shear_yield = physics::needs_shear_yield(friction);
  if (shear_yield)
    problem.set_contact_temperatures(law_temperatures(
        thermal,
        heat.contact_values(VectorX::Constant(heat.n_nodes(), thermal.billet_temperature))));
  VectorX previous = VectorX::Constant(heat.n_nodes(), thermal.billet_temperature);
  // Inexact staggering: a flow solve at a T that is still to move by a relative ΔT need
  // not be solved below ΔT/10 (the first one, at the billet's T, to 1e-2); the final
  // tolerance δ = solver.tolerance once ΔT/10 reaches it, and the coupling converges only
  // on a flow solved to δ.
  const auto inner_tolerance = [&](Real temperature_change) {
    return std::max(final_tolerance, std::min(first_flow_tolerance, 0.1 * temperature_change));
  };
  Real tolerance = inner_tolerance(1.0);
  solvers::SecantOutcome outcome = solve_flow(nullptr, tolerance);
  out.flow_iterations.push_back(static_cast<int>(outcome.history.size()));
  // history.csv and `iterations` count every flow iteration of every coupling step.
  std::vector<solvers::IterationRecord> history = outcome.history;
  Real previous_pressure = last_pressure(outcome);
  Real force_change = INFINITY; // no second flow solve yet
  std::optional<VectorX> T;     // the last heat solve
  bool current = false;         // T is the heat solve at outcome.velocity
  // Step k: the heat solve at the last velocity; converged when T moved by less than the
  // tolerance (relative to its rise) and the last two flow solves' pressures agree to it,
  // so that the flow is not solved again at a T it already has: the reported pair is that
  // velocity and the heat solve there (the flow was solved at the previous T, within the
  // coupling tolerance of this one). Otherwise the flow again, from the last velocity.
  for (int step = 1; step <= thermal.max_coupling_iterations; ++step) {
    if (outcome.stop_reason != solvers::StopReason::Converged) break; // its reason stands
    const auto start = Clock::now();
    T = heat_at(outcome.velocity);
    if (!T) {
      outcome.stop_reason = solvers::StopReason::SolverFailed;
      break;
    }
    current = true;
    const Real rise = std::max((T->array() - thermal.billet_temperature).abs().maxCoeff(),
                               std::numeric_limits<Real>::min());
    const Real temperature_change = (*T - previous).cwiseAbs().maxCoeff() / rise;
    out.coupling_iterations = step;
    out.temperature_change = temperature_change;
    const bool converged = temperature_change < thermal.coupling_tolerance &&
                           force_change < thermal.coupling_tolerance &&
                           tolerance <= final_tolerance;
    if (!converged && step < thermal.max_coupling_iterations) {
      problem.set_point_temperatures(law_temperatures(thermal, heat.point_values(*T)));
      if (shear_yield)
        problem.set_contact_temperatures(law_temperatures(thermal, heat.contact_values(*T)));
      const VectorX velocity = outcome.velocity;
      tolerance = inner_tolerance(temperature_change);
      outcome = solve_flow(&velocity, tolerance);
      current = false;
      out.flow_iterations.push_back(static_cast<int>(outcome.history.size()));
      history.insert(history.end(), outcome.history.begin(), outcome.history.end());
      const Real pressure = last_pressure(outcome);
      force_change = std::abs(pressure - previous_pressure) / std::max(std::abs(pressure), 1e-300);
      previous_pressure = pressure;
      previous = *T;
    }
    if (std::isfinite(force_change)) out.force_change = force_change;
    if (on_iteration) {
      solvers::IterationRecord record;
      record.iteration = step;
      record.coupling = step;
      record.relative_change = temperature_change;
      record.force_change = force_change;
      record.pressure = previous_pressure;
      record.max_temperature = T->maxCoeff();
      record.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      on_iteration(record);
    }
    if (converged) {
      out.coupling_converged = true;
      break;
    }
  }
  if (outcome.stop_reason == solvers::StopReason::Converged && !out.coupling_converged)
    outcome.stop_reason = solvers::StopReason::CouplingLimit;
  outcome.history = std::move(history);
  // What is reported: the heat solve at the final velocity (one more after a flow solve
  // that did not converge).
  if (!current) T = heat_at(outcome.velocity);
  const auto sources = sources_at(outcome.velocity);
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
template solvers::SecantOutcome couple_thermal<2>(const physics::Thermal&, const physics::Friction&,
                                                  Real, assembly::FormingProblem<2>&,
                                                  const FlowSolve&, const IterationCallback&,
                                                  const assembly::FrictionMultipliers<2>&,
                                                  post::Results&, const ManufacturedHeat<2>*);
template solvers::SecantOutcome couple_thermal<3>(const physics::Thermal&, const physics::Friction&,
                                                  Real, assembly::FormingProblem<3>&,
                                                  const FlowSolve&, const IterationCallback&,
                                                  const assembly::FrictionMultipliers<3>&,
                                                  post::Results&, const ManufacturedHeat<3>*);

} // namespace formflow::app
