// SPDX-License-Identifier: MIT
// The adaptive cycles: solve, estimate, mark, remesh, interpolate, solve again.
#include "formflow/app/adaptive_run.hpp"

#include "formflow/app/cheap_cycles.hpp"
#include "formflow/app/estimate_levels.hpp"
#include "formflow/app/load_error.hpp"
#include "formflow/core/error.hpp"
#include "formflow/core/parallel_tasks.hpp"
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/post/adaptivity.hpp"
#include "formflow/post/load_error_estimate.hpp"
#if FORMFLOW_WITH_GMSH
#include "formflow/mesh/die_face.hpp"
#include "formflow/mesh/gmsh_mesh.hpp"
#include "formflow/mesh/gmsh_meshers.hpp"
#endif

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace formflow::app {

namespace {

using Clock = std::chrono::steady_clock;

Real seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The process's CPU time so far (every thread's), for the cycles' `cpu_s`.
Real cpu_seconds() {
  return static_cast<Real>(std::clock()) / CLOCKS_PER_SEC;
}

/// When a cycle began, by the wall clock and the process's CPU time: what a cycle's
/// entry records as `time_s`, `cpu_s` and `estimate_time_s`.
struct CycleClock {
  Clock::time_point wall = Clock::now();
  Real cpu = cpu_seconds();

  /// The cycle's times up to now, its estimate's from the cycle's own phases.
  void stamp(post::AdaptCycle& entry, const post::Results& results) const {
    entry.seconds = seconds_since(wall);
    entry.cpu_seconds = cpu_seconds() - cpu;
    entry.estimate_seconds = results.timing.get("error estimate");
  }
};

/// |p_{h/2} − p|, the refined mesh's own error by the same argument as the cycle's
/// (post::load_error_bound): the tail beyond p_{h/2}, F_s |p_{h/2} − p_h| q/(1 − q)
/// (post::tail_beyond_refined), plus the penalties' offset. std::nullopt without a settled refined
/// solution or a penalty run (the cycle's estimate skipped it: its tail alone is above target).
std::optional<Real> refined_mesh_error(const post::LoadErrorEstimate& estimate, Real change) {
  if (estimate.refined_velocity.size() == 0 || !estimate.penalty_change) return std::nullopt;
  return post::tail_beyond_refined(change, estimate.ratio) + std::abs(*estimate.penalty_change);
}

/// The run on the estimate's refined mesh of the cycle that just ran (`simulation`),
/// Newton from the estimate's settled solution there, no estimate of its own.
Simulation simulate_on_refined_mesh(const RunPlan& run, const Simulation& simulation,
                                    bool mesh_from_plan, const CycleSolve& solve_cycle,
                                    const IterationCallback& on_iteration) {
  RunPlan last = run;
  last.solver.load_error = solvers::LoadErrorMethod::None;
  mesh::RefinedMesh<2> refined = estimate_mesh(run, simulation.plane_mesh(), mesh_from_plan);
  const VectorX& start = simulation.results.load_error.refined_velocity;
  const IterationCallback staged =
      with_stage(on_iteration, fmt::format("adapt: the last cycle's mesh split, {} dofs",
                                           2 * refined.mesh.n_nodes()));
  Simulation result = solve_cycle(last, &refined.mesh, &start, staged);
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
std::optional<Simulation> end_on_refined_mesh(const RunPlan& run, const Simulation& simulation,
                                              bool mesh_from_plan, const CycleClock& cycle_clock,
                                              post::AdaptCycle& entry, post::AdaptRecord& record,
                                              const CycleSolve& solve_cycle,
                                              const IterationCallback& on_iteration) {
  const post::LoadErrorEstimate& estimate = simulation.results.load_error;
  const Real target = run.adapt.cycle_target;
  const std::optional<Real> expected = refined_mesh_error(estimate, estimate.enriched_change);
  if (simulation.dimension() != 2 || !expected ||
      *expected > target * std::abs(entry.load + estimate.enriched_change))
    return std::nullopt;
  // The cycle's entry ends where the refined run begins (if it is kept).
  post::AdaptCycle cycle_entry = entry;
  cycle_clock.stamp(cycle_entry, simulation.results);
  const CycleClock refined_clock;
  Simulation last =
      simulate_on_refined_mesh(run, simulation, mesh_from_plan, solve_cycle, on_iteration);
  const post::Results& results = last.results;
  const std::optional<Real> error = results.load_error.error;
  const bool reached =
      results.converged() && error && *error <= target * std::abs(results.pressure.ram_reaction);
  // Not reached after all (the direct change exceeded the linearised one): go on from
  // the cycle's mesh as if the refined run had not been tried.
  if (results.converged() && !reached) return std::nullopt;
  entry = cycle_entry;
  record.cycles.push_back(entry);
  post::AdaptCycle final_entry;
  final_entry.cells = results.n_cells;
  final_entry.dofs = results.n_dofs;
  final_entry.load = results.pressure.ram_reaction;
  final_entry.estimate = error;
  final_entry.newton_iterations = results.iterations;
  final_entry.refined_mesh = true;
  refined_clock.stamp(final_entry, results);
  final_entry.estimate_seconds = 0; // its bar comes from the cycle's estimate
  record.cycles.push_back(final_entry);
  record.stop = reached ? "target reached on the refined mesh"
                        : "the run on the refined mesh did not converge";
  record.reached_target = reached;
  return last;
}

/// The plan of an intermediate cycle: the linearised estimate, indicators only.
RunPlan cheap_cycle_plan(const RunPlan& run) {
  RunPlan cheap = run;
  cheap.solver.load_error = solvers::LoadErrorMethod::Linearized;
  cheap.adapt.indicators_only = true;
  return cheap;
}

/// Replaces a cheap cycle's estimate by the full one (`run`'s) on the same solution.
void estimate_fully(const RunPlan& run, Simulation& simulation,
                    const IterationCallback& on_iteration) {
  post::Results& results = simulation.results;
  results.load_error = load_error_on<2>(run, simulation.plane_mesh(), results.fields.velocity,
                                        false, results.timing, on_iteration);
  results.fields.cell_load_error = results.load_error.cell_indicators;
}

/// Cycle 0 ran with the full estimate: its linearised change on the same solution
/// calibrates the cheap cycles that follow.
CheapCycles calibrate_on_first_cycle(const RunPlan& cheap, const Simulation& simulation) {
  CheapCycles plan;
  const post::Results& results = simulation.results;
  if (!results.converged() || !results.load_error.error) return plan;
  PhaseTimes times; // its time is in the cycle's total
  const post::LoadErrorEstimate linearised = std::visit(
      [&](const auto& mesh) {
        return load_error_on(cheap, mesh, results.fields.velocity, true, times);
      },
      simulation.mesh);
  if (linearised.cell_indicators.size() > 0)
    plan.calibrate(results.load_error, linearised.enriched_change);
  return plan;
}

} // namespace

Simulation simulate_adaptive(const RunPlan& plan, const IterationCallback& on_iteration,
                             const CycleSolve& solve_cycle) {
  FF_ASSERT(plan.adapt.enabled(), "adaptivity asked for");
  // Every cycle after the first remeshes with Gmsh: its module loads on another thread
  // while cycle 0 solves. The loops' helper threads start first, since a thread started
  // during that load would wait for it (0.35 s held up at cycle 0 before they did).
  start_task_helpers();
  mesh::preload_gmsh_meshers();
  RunPlan run = plan;
  run.adapt.target_error = 0; // each cycle is a plain run
  run.adapt.cycle_target = plan.adapt.target_error;
  // The stops are decided by the full ("refined") estimate. On Q2 the cycles before the
  // first one that may stop are cheap (step 2c of docs/error-estimation.md, with its
  // endgame: 22–53 % less time on the sticking ram and Hill's 15° wedge, 0–11 % more on
  // the 30°); solver.load_error = "refined" asks for the full estimate on every cycle,
  // "linearized" for the cheap cycles on Q1 too. Q1's settled/linearised ratio drifted
  // as the meshes grew (the ram: predictions 2.7× the error by 29 k dofs, the cycles ran
  // on to 65 k, 37 s against 14 s with full cycles), and calibrating again as they grow
  // cost the Q2 runs what the cheap cycles save (docs/error-estimation.md, session 20).
  const solvers::LoadErrorMethod asked = plan.solver.load_error;
  // A hot run's cycles all get the full estimate: its levels are hot runs, and the cheap
  // (linearised) estimate has no hot form.
  const bool cheap_cycles =
      !plan.thermal.enabled &&
      (asked == solvers::LoadErrorMethod::Linearized ||
       (asked != solvers::LoadErrorMethod::Refined && plan.element == fem::ElementKind::Q2));
  run.solver.load_error = solvers::LoadErrorMethod::Refined;
  const post::AdaptSettings& adapt = plan.adapt;
  post::AdaptRecord record;
  CycleClock cycle_clock;
  // The monitor's stage of cycle k's solves (its estimate's levels name themselves).
  const auto cycle_stage = [&on_iteration](int cycle, const mesh::Mesh<2>* mesh) {
    return with_stage(on_iteration,
                      mesh ? fmt::format("adapt cycle {}, {} dofs", cycle, 2 * mesh->n_nodes())
                           : fmt::format("adapt cycle {}, the case's mesh", cycle));
  };
  IterationCallback staged = cycle_stage(0, nullptr);
  Simulation simulation = solve_cycle(run, nullptr, nullptr, staged); // cycle 0: the plan's mesh
  // Later cycles mark with the cheap estimate; the full one only where it may stop.
  const RunPlan cheap = cheap_cycle_plan(run);
  CheapCycles predictions =
      cheap_cycles ? calibrate_on_first_cycle(cheap, simulation) : CheapCycles{};
  bool cheap_cycle = false;
  for (int cycle = 0;; ++cycle) {
    const post::Results& results = simulation.results;
    post::AdaptCycle entry;
    entry.cells = results.n_cells;
    entry.dofs = results.n_dofs;
    entry.load = results.pressure.ram_reaction;
    entry.newton_iterations = results.iterations;
    const auto finish = [&](std::string why, bool reached = false) {
      cycle_clock.stamp(entry, results);
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
    // A cheap cycle whose prediction is above the target only marks; one that may stop
    // (and the last cycle, whatever stops it) gets the full estimate, which decides.
    bool fully_estimated = !cheap_cycle;
    const auto estimate_fully_once = [&] {
      if (!fully_estimated) estimate_fully(run, simulation, staged);
      fully_estimated = true;
      entry.estimate = results.load_error.error;
      entry.estimate_predicted = false;
    };
    bool may_stop = !cheap_cycle;
    if (cheap_cycle) {
      const CheapCycles::Prediction prediction = predictions.predict(
          results.load_error.enriched_change, results.pressure.ram_reaction, adapt.target_error);
      entry.estimate = prediction.estimate;
      entry.estimate_predicted = true;
      may_stop = prediction.may_stop;
      if (may_stop) predictions.prediction_called_for_full_estimate();
    }
    if (may_stop) {
      estimate_fully_once();
      if (!results.load_error.error) {
        finish("no error estimate: " + results.load_error.unavailable);
        break;
      }
      if (*entry.estimate <= adapt.target_error * std::abs(entry.load)) {
        finish("target reached", true);
        break;
      }
      // The bar holds the regularisations' offset, which no mesh lowers: once it alone
      // is above the target, further cycles only cost (the ram with Coulomb friction
      // μ = 0.1: 0.0028, from d, against a target of 0.0027; three more cycles to 150 k
      // dofs, 100 s).
      if (const std::optional<Real> offset = results.load_error.penalty_change;
          offset && std::abs(*offset) >= adapt.target_error * std::abs(entry.load)) {
        // Which key to lower: each doubled alone on this cycle's mesh (a few solves from
        // the converged field, made once, when the run stops).
        // (A hot run's doubled runs would each be hot runs: its message names them all.)
        std::string keys;
        if (!run.thermal.enabled)
          for (const auto& [key, change] : regularisation_offsets<2>(
                   run, simulation.plane_mesh(), results.fields.velocity, entry.load))
            keys += fmt::format("{}{} ({:.2g})", keys.empty() ? "" : ", ", key, std::abs(change));
        finish(fmt::format(
            "the regularisations' offset |p(2ε) − p(ε)| = {:.3g} alone is at least the target "
            "{:.3g} (adapt.target_error × |p|), and refining the mesh does not lower it: lower "
            "the regularisations, largest offset first when doubled alone: {}; or raise "
            "adapt.target_error",
            std::abs(*offset), adapt.target_error * std::abs(entry.load),
            keys.empty() ? std::string("penalty.d, penalty.d_n, friction.d_t, material.alpha")
                         : keys));
        break;
      }
      // The estimate's refined mesh, whose settled solution is at hand, may already be
      // accurate enough: solve there to δ and end on it, its load as the result.
      if (std::optional<Simulation> last = end_on_refined_mesh(
              run, simulation, cycle == 0, cycle_clock, entry, record, solve_cycle, on_iteration)) {
        simulation = std::move(*last);
        break;
      }
    }
    if (cycle + 1 >= adapt.max_cycles) {
      estimate_fully_once(); // the result's error bar is the full estimate
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
      estimate_fully_once();
      finish("max_dofs");
      break;
    }
#if FORMFLOW_WITH_GMSH
    const mesh::Mesh<2>& current = simulation.plane_mesh();
    mesh::Mesh<2> next;
    try {
      next = mesh::gmsh_meshers().sized_channel_mesh(
          run.mesh.geometry, mesh::die_face_polyline(run.mesh.geometry, run.mesh.size), current,
          post::target_node_sizes(
              current, marked,
              post::coarsening_marking(results.load_error.cell_indicators, adapt.coarsen_fraction),
              run.mesh.size),
          current.order);
    } catch (const mesh::MeshFileError& error) {
      // Gmsh could not make the sized mesh (e.g. left triangles it could not recombine):
      // the run ends on this cycle, its bar the full estimate, and says why.
      estimate_fully_once();
      finish(fmt::format("the remesh for the next cycle failed: {}", error.what()));
      break;
    }
    if (run.problem.process.type == physics::ProcessType::Drawing) mesh::free_container_wall(next);
    const VectorX start = fem::interpolate_nodal_field(current, results.fields.velocity, 2, next);
    cycle_clock.stamp(entry, results);
    record.cycles.push_back(entry);
    cycle_clock = CycleClock{};
    cheap_cycle = predictions.next_cycle_cheap();
    staged = cycle_stage(cycle + 1, &next);
    simulation = solve_cycle(cheap_cycle ? cheap : run, &next, &start, staged);
#else
    finish("adaptivity needs Gmsh (FORMFLOW_WITH_GMSH=OFF)");
    break;
#endif
  }
  // The other phases are the last cycle's; "total" is the whole run's (every cycle),
  // added by the run around this stage (app/run.cpp).
  simulation.results.adapt = std::move(record);
  return simulation;
}

} // namespace formflow::app
