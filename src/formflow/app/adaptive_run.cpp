// SPDX-License-Identifier: MIT
// The adaptive cycles: solve, estimate, mark, remesh, interpolate, solve again.
#include "formflow/app/adaptive_run.hpp"

#include "formflow/app/load_error.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/post/adaptivity.hpp"
#if FORMFLOW_WITH_GMSH
#include "formflow/mesh/gmsh_channel.hpp"
#include "formflow/mesh/gmsh_sized_channel.hpp"
#endif

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace formflow::app {

namespace {

using Clock = std::chrono::steady_clock;

Real seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// |p_{h/2} − p|, the refined mesh's own error by the same argument as the cycle's
/// (post::load_error_bound): the tail beyond p_{h/2}, |p_{h/2} − p_h| q/(1 − q), plus
/// the penalties' offset. std::nullopt without a settled refined solution or a
/// penalty run (the cycle's estimate skipped it: its tail alone is above target).
std::optional<Real> refined_mesh_error(const post::LoadErrorEstimate& estimate, Real change) {
  if (estimate.refined_velocity.size() == 0 || !estimate.penalty_change) return std::nullopt;
  return std::abs(change) * estimate.ratio / (1.0 - estimate.ratio) +
         std::abs(*estimate.penalty_change);
}

/// The run on the estimate's refined mesh of the cycle that just ran (`simulation`),
/// Newton from the estimate's settled solution there, no estimate of its own.
Simulation simulate_on_refined_mesh(const io::Case& run, const Simulation& simulation,
                                    bool mesh_from_case, const IterationCallback& on_iteration) {
  io::Case last = run;
  last.solver.load_error = solvers::LoadErrorMethod::None;
  mesh::RefinedMesh<2> refined = estimate_mesh(run, simulation.plane_mesh(), mesh_from_case);
  const VectorX& start = simulation.results.load_error.refined_velocity;
  Simulation result = simulate_from<2>(last, std::move(refined.mesh), start, on_iteration);
  // Its error bar (refined_mesh_error) and the cycle's indicators, each parent's
  // shared among its children (a density on the mesh that ran last).
  post::LoadErrorEstimate estimate = simulation.results.load_error;
  estimate.refined_velocity = VectorX();
  estimate.of_refined_mesh = true;
  std::vector<int> children(static_cast<std::size_t>(estimate.cell_indicators.size()), 0);
  for (Index parent : refined.parent) ++children[static_cast<std::size_t>(parent)];
  VectorX shares(static_cast<Index>(refined.parent.size()));
  for (std::size_t cell = 0; cell < refined.parent.size(); ++cell) {
    const Index parent = refined.parent[cell];
    shares[static_cast<Index>(cell)] =
        estimate.cell_indicators[parent] / children[static_cast<std::size_t>(parent)];
  }
  estimate.cell_indicators = shares;
  const Real change =
      result.results.pressure.ram_reaction - simulation.results.pressure.ram_reaction;
  estimate.error = refined_mesh_error(simulation.results.load_error, change);
  result.results.load_error = std::move(estimate);
  result.results.fields.cell_load_error = result.results.load_error.cell_indicators;
  return result;
}

/// The run on the refined mesh of the cycle that just ran, if the cycle's estimate of
/// that mesh's error (refined_mesh_error with the linearised change) is within the
/// target: returned, with `entry` and the refined mesh's entry appended to `record`
/// and its stop reason set, when it ends the adaptive run (the target reached there
/// with the direct change, or it did not converge); std::nullopt to go on cycling.
std::optional<Simulation> end_on_refined_mesh(const io::Case& run, const Simulation& simulation,
                                              bool mesh_from_case, Clock::time_point cycle_start,
                                              post::AdaptCycle& entry, post::AdaptRecord& record,
                                              const IterationCallback& on_iteration) {
  const post::LoadErrorEstimate& estimate = simulation.results.load_error;
  const Real target = run.adapt.cycle_target;
  const std::optional<Real> expected = refined_mesh_error(estimate, estimate.enriched_change);
  if (simulation.dimension() != 2 || !expected ||
      *expected > target * std::abs(entry.load + estimate.enriched_change))
    return std::nullopt;
  const auto refined_start = Clock::now();
  Simulation last = simulate_on_refined_mesh(run, simulation, mesh_from_case, on_iteration);
  const post::Results& results = last.results;
  const std::optional<Real> error = results.load_error.error;
  const bool reached =
      results.converged() && error && *error <= target * std::abs(results.pressure.ram_reaction);
  // Not reached after all (the direct change exceeded the linearised one): go on from
  // the cycle's mesh as if the refined run had not been tried.
  if (results.converged() && !reached) return std::nullopt;
  entry.seconds = std::chrono::duration<double>(refined_start - cycle_start).count();
  record.cycles.push_back(entry);
  post::AdaptCycle final_entry;
  final_entry.cells = results.n_cells;
  final_entry.dofs = results.n_dofs;
  final_entry.load = results.pressure.ram_reaction;
  final_entry.estimate = error;
  final_entry.newton_iterations = results.iterations;
  final_entry.refined_mesh = true;
  final_entry.seconds = seconds_since(refined_start);
  record.cycles.push_back(final_entry);
  record.stop = reached ? "target reached on the refined mesh"
                        : "the run on the refined mesh did not converge";
  record.reached_target = reached;
  return last;
}

} // namespace

Simulation simulate_adaptive(const io::Case& case_, const IterationCallback& on_iteration) {
  FF_ASSERT(case_.adapt.enabled(), "adaptivity asked for");
  const auto run_start = Clock::now();
  io::Case run = case_;
  run.adapt.target_error = 0; // each cycle is a plain run
  run.adapt.cycle_target = case_.adapt.target_error;
  if (run.solver.load_error == solvers::LoadErrorMethod::None)
    run.solver.load_error = solvers::LoadErrorMethod::Refined; // the indicators drive it
  const post::AdaptSettings& adapt = case_.adapt;
  post::AdaptRecord record;
  auto cycle_start = Clock::now();
  Simulation simulation = simulate(run, on_iteration); // cycle 0: the case's mesh
  for (int cycle = 0;; ++cycle) {
    const post::Results& results = simulation.results;
    post::AdaptCycle entry;
    entry.cells = results.n_cells;
    entry.dofs = results.n_dofs;
    entry.load = results.pressure.ram_reaction;
    entry.newton_iterations = results.iterations;
    const auto finish = [&](std::string why, bool reached = false) {
      entry.seconds = seconds_since(cycle_start);
      record.cycles.push_back(entry);
      record.stop = std::move(why);
      record.reached_target = reached;
    };
    if (!results.converged()) {
      finish(fmt::format("cycle {} did not converge", cycle));
      break;
    }
    if (!results.load_error.error) {
      finish("no error estimate: " + results.load_error.unavailable);
      break;
    }
    entry.estimate = *results.load_error.error;
    if (*entry.estimate <= adapt.target_error * std::abs(entry.load)) {
      finish("target reached", true);
      break;
    }
    // The estimate's refined mesh, whose settled solution is at hand, may already be
    // accurate enough: solve there to δ and end on it, its load as the result.
    if (std::optional<Simulation> last = end_on_refined_mesh(
            run, simulation, cycle == 0, cycle_start, entry, record, on_iteration)) {
      simulation = std::move(*last);
      break;
    }
    if (cycle + 1 >= adapt.max_cycles) {
      finish("max_cycles");
      break;
    }
    if (simulation.dimension() != 2) {
      finish("adaptivity remeshes plane channels only");
      break;
    }
    const std::vector<bool> marked =
        post::dorfler_marking(results.load_error.cell_indicators, adapt.fraction);
    entry.marked = std::count(marked.begin(), marked.end(), true);
    // A marked cell becomes about four: the next mesh's dofs grow by that share.
    const Real growth =
        1.0 + 3.0 * static_cast<Real>(entry.marked) / std::max<Index>(1, entry.cells);
    if (static_cast<Real>(entry.dofs) * growth > static_cast<Real>(adapt.max_dofs)) {
      finish("max_dofs");
      break;
    }
#if FORMFLOW_WITH_GMSH
    const mesh::Mesh<2>& current = simulation.plane_mesh();
    mesh::Mesh<2> next = mesh::make_sized_gmsh_channel_mesh(
        run.mesh.geometry, mesh::die_face_polyline(run.mesh.geometry, run.mesh.size), current,
        post::target_node_sizes(current, marked), current.order);
    if (run.process.type == physics::ProcessType::Drawing) mesh::free_container_wall(next);
    const VectorX start = fem::interpolate_nodal_field(current, results.fields.velocity, 2, next);
    entry.seconds = seconds_since(cycle_start);
    record.cycles.push_back(entry);
    cycle_start = Clock::now();
    simulation = simulate_from<2>(run, std::move(next), start, on_iteration);
#else
    finish("adaptivity needs Gmsh (FORMFLOW_WITH_GMSH=OFF)");
    break;
#endif
  }
  simulation.results.adapt = std::move(record);
  // "total" is the whole run's (every cycle), the other phases the last cycle's.
  PhaseTimes& timing = simulation.results.timing;
  timing.add("total", seconds_since(run_start) - timing.get("total"));
  return simulation;
}

} // namespace formflow::app
