// SPDX-License-Identifier: MIT
// Solve on 2^L h, ..., 2h, interpolating each solution to the next mesh.
#include "formflow/app/coarse_start.hpp"
#include "formflow/app/solve_plan.hpp"

#include "formflow/app/simulation.hpp"
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/io/mesh_input.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/newton_iteration.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace formflow::app {

namespace {

/// The coarse levels stop at this relative change (or the case's δ if larger):
/// measured at h = 0.125, μ = 0 (coarse mesh 0.25), coarse δ = 1e-2, 1e-4 and 1e-7
/// (6, 10 and 13 coarse iterations) give the same fine-mesh history to two digits,
/// since the coarse and fine solutions differ by ≈ 4e-2 (the first fine change).
constexpr Real coarse_tolerance = 1e-2;

/// Whether a structured channel mesh of `size` can be made for `case_`: every
/// length the generator divides is a multiple of it (the case validation's test
/// for mesh.size, io/case_file.cpp) and the exit keeps fewer cells than the entry.
bool structured_size_fits(const io::Case& case_, Real size) {
  const mesh::ChannelGeometry& g = case_.geometry;
  std::vector<Real> lengths = {g.container_length, g.entry_half_height, g.exit_length};
  if (g.die == mesh::DieShape::Square) lengths.push_back(g.exit_half_height);
  if (g.land_length > 0) lengths.push_back(g.land_length);
  for (Real length : lengths)
    if (mesh::cells_along(length, size) <= 0) return false;
  return mesh::cells_along(g.exit_half_height, size) < mesh::cells_along(g.entry_half_height, size);
}

} // namespace

std::optional<CoarseStart> coarse_start(const io::Case& case_, const mesh::Mesh<2>& fine,
                                        PhaseTimes& times) {
  if (case_.mesh_source == mesh::MeshSource::File) return std::nullopt;
  // As many of the asked levels as the geometry admits (2^L h must divide its lengths).
  int levels = 0;
  while (levels < case_.solver.coarse_levels &&
         (case_.mesh_source != mesh::MeshSource::Structured ||
          structured_size_fits(case_, case_.mesh_size * std::ldexp(1.0, levels + 1))))
    ++levels;
  if (levels == 0) return std::nullopt;
  CoarseStart start;
  mesh::Mesh<2> previous_mesh;
  VectorX previous_velocity;
  for (int level = levels; level >= 1; --level) {
    io::Case coarse = case_;
    coarse.mesh_size = case_.mesh_size * std::ldexp(1.0, level);
    coarse.solver.coarse_levels = 0;
    coarse.solver.tolerance = std::max(case_.solver.tolerance, coarse_tolerance);
    mesh::Mesh<2> mesh;
    std::unique_ptr<assembly::FormingProblem<2>> problem;
    std::unique_ptr<assembly::ConstraintMultipliers<2>> mixed_pressure;
    VectorX guess;
    {
      ScopedTimer timer(times, "coarse start");
      mesh = io::load_mesh(coarse);
      problem = std::make_unique<assembly::FormingProblem<2>>(mesh, problem_settings(coarse));
      // The same discrete problem on the coarse mesh: the mixed formulation keeps its
      // condensed pressure (Newton runs mixed cases only with d > 0, d_N > 0).
      if (coarse.formulation.type == assembly::FormulationType::Mixed) {
        mixed_pressure = std::make_unique<assembly::ConstraintMultipliers<2>>(
            mesh, coarse.penalty, coarse.formulation, problem->full_rule(),
            problem->n_contact_points());
        problem->attach_multipliers(mixed_pressure.get());
      }
      if (level < levels)
        guess = fem::interpolate_nodal_field(previous_mesh, previous_velocity, 2, mesh);
    }
    auto solver = solvers::make_linear_solver(make_solve_plan(case_).linear,
                                              solvers::MatrixStorage::SymmetricLower);
    solvers::FormingNonlinearProblem<2> nonlinear(*problem);
    solvers::SecantOutcome outcome = solvers::newton_iteration(
        nonlinear, *solver, coarse.solver, {}, times, level < levels ? &guess : nullptr);
    start.mesh_sizes.push_back(coarse.mesh_size);
    start.iterations.push_back(static_cast<int>(outcome.history.size()));
    start.converged = start.converged && outcome.stop_reason == solvers::StopReason::Converged;
    previous_mesh = std::move(mesh);
    previous_velocity = std::move(outcome.velocity);
  }
  ScopedTimer timer(times, "coarse start");
  start.velocity = fem::interpolate_nodal_field(previous_mesh, previous_velocity, 2, fine);
  return start;
}

} // namespace formflow::app
