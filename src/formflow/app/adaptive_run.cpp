// SPDX-License-Identifier: MIT
// The adaptive cycles: solve, estimate, mark, remesh, interpolate, solve again.
#include "formflow/app/adaptive_run.hpp"

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

} // namespace

Simulation simulate_adaptive(const io::Case& case_, const IterationCallback& on_iteration) {
  FF_ASSERT(case_.adapt.enabled(), "adaptivity asked for");
  const auto run_start = Clock::now();
  io::Case run = case_;
  run.adapt.target_error = 0; // each cycle is a plain run
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
