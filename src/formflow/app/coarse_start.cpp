// SPDX-License-Identifier: MIT
// Solve on 2^L h, ..., 2h, interpolating each solution to the next mesh.
#include "formflow/app/coarse_start.hpp"

#include "formflow/app/run.hpp"
#include "formflow/assembly/contact_normal_velocity.hpp"
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/mesh/solid_channel_mesh.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/newton_iteration.hpp"
#include "formflow/solvers/saddle_point_iteration.hpp"

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

/// Whether a structured channel mesh of `size` can be made for `geometry`: every
/// length the generator divides is a multiple of it (the case validation's test
/// for mesh.size, io/plancross_checks.cpp) and the exit keeps fewer cells than the entry.
bool structured_size_fits(const mesh::ChannelGeometry& g, Real size) {
  std::vector<Real> lengths = {g.container_length, g.entry_half_height, g.exit_length};
  if (g.die == mesh::DieShape::Square) lengths.push_back(g.exit_half_height);
  if (g.land_length > 0) lengths.push_back(g.land_length);
  for (Real length : lengths)
    if (mesh::cells_along(length, size) <= 0) return false;
  return mesh::cells_along(g.exit_half_height, size) < mesh::cells_along(g.entry_half_height, size);
}

/// How the coarse levels solve the case (the fine mesh's loop is the plan's).
enum class CoarseLoop {
  /// Newton with the case's linear solver: the case's own loop is Newton.
  Newton,
  /// A discontinuous pressure kept as a saddle point, d > 0 and d_N > 0: the same discrete
  /// problem with the pressure condensed cell by cell (exact: p = (1/d) M⁻¹ B u per cell),
  /// by Newton on CHOLMOD. Why not the saddle point itself: Newton takes 6–9 steps where
  /// the secant loop takes 18–26 (3D) or 60–136 (2D), and a CHOLMOD factorisation of a
  /// level with 1/8 (3D) of the fine dofs costs a tenth of an AMG-preconditioned Krylov
  /// solve there (docs/benchmarks.md "Crossover": 2.5 s against 21 s for the whole run at
  /// 7 137 dofs, 27 s against 410 s at 48 825).
  CondensedNewton,
  /// The saddle point's own secant loop with the case's solver (d = 0 or d_N = 0: no
  /// pressure to condense, or contact multipliers; Taylor–Hood never comes here).
  SaddlePointSecant,
};

CoarseLoop coarse_loop(const SolvePlan& plan) {
  if (plan.loop != solvers::LoopKind::SaddlePointSecant) return CoarseLoop::Newton;
  return plan.shape.exact_incompressibility || plan.shape.exact_contact
             ? CoarseLoop::SaddlePointSecant
             : CoarseLoop::CondensedNewton;
}

/// A coarse level's velocity on the next mesh: interpolated, with its Γ3 nodes' normal
/// velocity interpolated as a scalar of its own and set on the next mesh's Γ3 nodes
/// (assembly::set_contact_normal_velocity says why).
template <int dim>
VectorX carried_over(const mesh::Mesh<dim>& from, const VectorX& velocity,
                     const VectorX& normal_velocity, const assembly::Discretisation<dim>& to) {
  VectorX carried = fem::interpolate_nodal_field(from, velocity, dim, to.mesh());
  const VectorX normal = fem::interpolate_nodal_field(from, normal_velocity, 1, to.mesh());
  assembly::set_contact_normal_velocity(to, normal, carried);
  return carried;
}

} // namespace

bool size_fits(const mesh::MeshSpec& spec, Real size) {
  return spec.dimension == 3 ? mesh::solid_lengths_fit(spec.geometry, spec.solid, size)
                             : structured_size_fits(spec.geometry, size);
}

template <int dim>
std::optional<CoarseStart>
coarse_start(const RunPlan& plan, const assembly::Discretisation<dim>& fine, PhaseTimes& times) {
  if (plan.mesh.source == mesh::MeshSource::File) return std::nullopt;
  // As many of the asked levels as the geometry admits (2^L h must divide its lengths).
  int levels = 0;
  // A profile's coarse level must still tell each bearing's end: its bearing cells, as
  // coarse as its cells, no longer than the shortest bearing (the case's own rule).
  const bool profile =
      plan.mesh.dimension == 3 && plan.mesh.solid.section == mesh::ChannelSection::Profile;
  const auto level_fits = [&](int level) {
    const Real factor = std::ldexp(1.0, level);
    if (profile)
      return factor * plan.mesh.bearing_cell() <= plan.mesh.solid.profile.shortest_bearing();
    return plan.mesh.source != mesh::MeshSource::Structured ||
           size_fits(plan.mesh, plan.mesh.size * factor);
  };
  while (levels < plan.solver.coarse_levels && level_fits(levels + 1)) ++levels;
  if (levels == 0) return std::nullopt;
  CoarseStart start;
  const SolvePlan& solve = plan.solve;
  const CoarseLoop loop = coarse_loop(solve);
  // The levels' iteration control: no nesting of their own, a looser tolerance.
  solvers::IterationControl control = plan.solver;
  control.coarse_levels = 0;
  control.tolerance = std::max(plan.solver.tolerance, coarse_tolerance);
  // The discrete problem is the case's on every level: only the mesh differs (and how a
  // discontinuous pressure is solved, which does not change the problem).
  const assembly::ProblemSettings settings = plan.problem;
  assembly::Formulation formulation = plan.formulation;
  if (loop == CoarseLoop::CondensedNewton)
    formulation.discontinuous = assembly::DiscontinuousPressure::Condensed;
  mesh::Mesh<dim> previous_mesh;
  VectorX previous_velocity, previous_normal_velocity;
  for (int level = levels; level >= 1; --level) {
    mesh::MeshSpec spec = plan.mesh;
    spec.size = plan.mesh.size * std::ldexp(1.0, level);
    spec.bearing_size = plan.mesh.bearing_size * std::ldexp(1.0, level); // 0 stays size / 2
    mesh::Mesh<dim> mesh;
    std::unique_ptr<assembly::FormingProblem<dim>> problem;
    std::unique_ptr<assembly::ConstraintMultipliers<dim>> mixed_pressure;
    VectorX guess;
    {
      ScopedTimer timer(times, "coarse start");
      mesh = std::get<mesh::Mesh<dim>>(plan.make_mesh(spec)); // one source, one dimension
      problem = std::make_unique<assembly::FormingProblem<dim>>(mesh, settings);
      // The same discrete problem on the coarse mesh: the mixed formulation keeps its
      // pressure (condensed for Newton, which runs mixed cases only with d > 0, d_N > 0).
      if (plan.formulation.type == assembly::FormulationType::Mixed) {
        mixed_pressure = std::make_unique<assembly::ConstraintMultipliers<dim>>(
            mesh, plan.problem.penalty, formulation, problem->full_rule(),
            problem->n_contact_points(), problem->discretisation().axisymmetric());
        problem->attach_multipliers(mixed_pressure.get());
      }
      if (level < levels)
        guess = carried_over(previous_mesh, previous_velocity, previous_normal_velocity,
                             problem->discretisation());
    }
    const VectorX* level_start = level < levels ? &guess : nullptr;
    solvers::FormingNonlinearProblem<dim> nonlinear(*problem);
    solvers::SecantOutcome outcome;
    if (loop == CoarseLoop::SaddlePointSecant) {
      auto solver = solvers::make_linear_solver(solve.linear, solvers::MatrixStorage::Full,
                                                plan.solver.petsc_options);
      solvers::TimedLinearStep linear(*solver, times);
      solvers::SaddlePointSolve<dim> saddle(nonlinear, linear);
      outcome = solvers::secant_iteration(nonlinear, saddle, control, {}, level_start);
    } else {
      // On several ranks CHOLMOD cannot take a rank's share: the case's back-end (PETSc),
      // direct MUMPS Cholesky. The run's PETSc options (the case's and the command line's)
      // are the saddle point's: this level's solver reads only -coarse_* ones, and leaves the
      // check for unread options to the fine solve.
      const bool condensed = loop == CoarseLoop::CondensedNewton;
      const bool distributed = settings.distribution.distributed();
      const solvers::LinearSolverKind kind =
          condensed && !distributed ? solvers::LinearSolverKind::Cholmod : solve.linear;
      auto solver =
          solvers::make_linear_solver(kind, solvers::MatrixStorage::SymmetricLower,
                                      condensed ? std::string() : plan.solver.petsc_options);
      if (condensed && distributed) solver->set_options_prefix("coarse_");
      outcome = solvers::newton_iteration(nonlinear, *solver, control, {}, times, level_start);
    }
    nonlinear.replicate(outcome.velocity); // ghosted on several ranks; interpolated whole
    start.mesh_sizes.push_back(spec.size);
    start.iterations.push_back(static_cast<int>(outcome.history.size()));
    start.converged = start.converged && outcome.stop_reason == solvers::StopReason::Converged;
    previous_normal_velocity =
        assembly::contact_normal_velocity(problem->discretisation(), outcome.velocity);
    previous_mesh = std::move(mesh);
    previous_velocity = std::move(outcome.velocity);
  }
  ScopedTimer timer(times, "coarse start");
  start.velocity = carried_over(previous_mesh, previous_velocity, previous_normal_velocity, fine);
  return start;
}

template std::optional<CoarseStart>
coarse_start<2>(const RunPlan&, const assembly::Discretisation<2>&, PhaseTimes&);
template std::optional<CoarseStart>
coarse_start<3>(const RunPlan&, const assembly::Discretisation<3>&, PhaseTimes&);

} // namespace formflow::app
