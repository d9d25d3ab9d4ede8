// SPDX-License-Identifier: MIT
// One case from parameters to results, in the dimension of its mesh.
#include "formflow/app/simulation.hpp"
#include "formflow/app/adaptive_run.hpp"
#include "formflow/app/coarse_start.hpp"
#include "formflow/app/distributed_run.hpp"
#include "formflow/app/load_error.hpp"
#include "formflow/app/solve_plan.hpp"
#include "formflow/app/thermal_coupling.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/mesh_input.hpp"
#include "formflow/io/problem_shape.hpp"
#include "formflow/post/post_process.hpp"
#include "formflow/solvers/augmented_lagrangian.hpp"
#include "formflow/solvers/augmented_newton.hpp"
#include "formflow/solvers/condition_estimate.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/newton_iteration.hpp"
#include "formflow/solvers/pattern_reuse.hpp"
#include "formflow/solvers/saddle_point_iteration.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <chrono>
#include <memory>
#include <variant>

namespace formflow::app {

assembly::ProblemSettings problem_settings(const io::Case& case_) {
  assembly::ProblemSettings settings;
  settings.process = case_.process;
  settings.law = case_.material.selected();
  // Hot forming: what is not at a point's temperature (the constant-viscosity start, the
  // coarse levels of mesh sequencing) is at the billet's.
  if (case_.thermal.enabled)
    std::visit(
        [&](auto& law) {
          if constexpr (physics::TemperatureDependent<std::decay_t<decltype(law)>>)
            law.temperature =
                std::min(case_.thermal.billet_temperature, case_.thermal.max_temperature);
        },
        settings.law.model);
  settings.viscous_strain = case_.viscous_strain;
  settings.penalty = case_.penalty;
  settings.friction = case_.friction;
  // The augmentation of the loop that runs (friction.newton_augmentation for Newton's).
  settings.friction.augmentation = make_solve_plan(case_).friction_augmentation;
  settings.volumetric_points = case_.volumetric_points;
  settings.initial_rate = case_.solver.initial_rate;
  settings.symmetry = case_.symmetry;
  // Nodal points where exact stick runs, though contact.normals was not given.
  settings.contact = io::contact_settings(case_);
  settings.distribution = distribution(); // one rank's own cells in a distributed run
  return settings;
}

template <int dim>
Real condition_at(const assembly::FormingProblem<dim>& problem, const VectorX& u) {
  assembly::LinearSystem system = problem.plan().make_system();
  problem.assemble(&u, system);
  return solvers::reciprocal_condition_estimate(system.matrix);
}

namespace {

using Clock = std::chrono::steady_clock;

/// Runs the nonlinear loop the plan chose on `problem` from `start_velocity`
/// (nullptr: the loop's own start); exact friction's final multipliers go to
/// `multipliers`.
template <int dim>
solvers::SecantOutcome
run_loop(const SolvePlan& plan, const io::Case& case_, const assembly::FormingProblem<dim>& problem,
         solvers::LinearSolver& solver, const IterationCallback& on_iteration,
         post::Results& results, const VectorX* start_velocity,
         assembly::FrictionMultipliers<dim>& multipliers);

/// The Krylov iterations of each recorded iteration, from the solver's running
/// count: the observer sees them on its record, and the history gets them after
/// the loop (the drivers record before they call the observer).
class KrylovCounter {
public:
  KrylovCounter(const solvers::LinearSolver& solver, const IterationCallback& on_iteration)
      : solver_(solver), on_iteration_(on_iteration), seen_(solver.krylov_iterations()) {}
  IterationCallback observer() {
    return [this](const solvers::IterationRecord& record) {
      solvers::IterationRecord counted = record;
      const long total = solver_.krylov_iterations();
      counted.linear_iterations = total < 0 ? -1 : total - seen_;
      seen_ = total;
      per_iteration_.push_back(counted.linear_iterations);
      if (on_iteration_) on_iteration_(counted);
    };
  }
  void fill(std::vector<solvers::IterationRecord>& history) const {
    for (std::size_t i = 0; i < history.size() && i < per_iteration_.size(); ++i)
      history[i].linear_iterations = per_iteration_[i];
  }

private:
  const solvers::LinearSolver& solver_;
  const IterationCallback& on_iteration_;
  long seen_;
  std::vector<long> per_iteration_;
};

/// The linear solver the plan names.
std::unique_ptr<solvers::LinearSolver> plan_solver(const SolvePlan& plan, const io::Case& case_) {
  return solvers::make_linear_solver(plan.linear, solvers::loop_storage(plan.loop),
                                     case_.solver.petsc_options);
}

/// The loop of the plan with `solver`; the linear algebra's record in `results` (the
/// Krylov count is the solver's running total: every loop that used it).
/// Per rank, the dofs it owns and its ghosts (gathered by a sum: each rank fills its
/// slots); empty on one rank.
template <int dim>
std::vector<std::pair<Index, Index>>
rank_dofs(const assembly::Discretisation<dim>& discretisation) {
  const assembly::Distribution& distribution = discretisation.distribution();
  if (!distribution.distributed()) return {};
  std::vector<Real> counts(2 * static_cast<std::size_t>(distribution.size), 0.0);
  counts[2 * distribution.rank] = static_cast<Real>(discretisation.owned_dofs().n_owned());
  counts[2 * distribution.rank + 1] = static_cast<Real>(discretisation.owned_dofs().n_ghosts());
  distribution.sum_over_ranks(counts);
  std::vector<std::pair<Index, Index>> ranks;
  for (int r = 0; r < distribution.size; ++r)
    ranks.emplace_back(static_cast<Index>(counts[2 * r]), static_cast<Index>(counts[2 * r + 1]));
  return ranks;
}

template <int dim>
solvers::SecantOutcome
run_counted_loop(const SolvePlan& plan, const io::Case& case_,
                 const assembly::FormingProblem<dim>& problem, solvers::LinearSolver& solver,
                 const IterationCallback& on_iteration, post::Results& results,
                 const VectorX* start_velocity, assembly::FrictionMultipliers<dim>& multipliers) {
  KrylovCounter counter(solver, on_iteration);
  solvers::SecantOutcome outcome = run_loop(plan, case_, problem, solver, counter.observer(),
                                            results, start_velocity, multipliers);
  counter.fill(outcome.history);
  // A distributed loop's velocity is ghosted (each rank its own cells' dofs); the
  // post-processing and the writers read it whole (docs/petsc.md "Distributed runs").
  problem.discretisation().owned_dofs().replicate(outcome.velocity);
  results.linear_algebra.solver = solver.name(); // e.g. "petsc-gmres-cholesky"
  results.linear_algebra.iterations = solver.krylov_iterations();
  const solvers::FactorSize factor = solver.factor_size(); // the fine mesh's pattern
  results.linear_algebra.matrix_nonzeros = factor.matrix_nonzeros;
  results.linear_algebra.factor_nonzeros = factor.factor_nonzeros;
  results.linear_algebra.factor_flops = factor.factor_flops;
  results.linear_algebra.ranks = distribution().size;
  results.cell_ranks = problem.discretisation().cell_ranks();
  results.linear_algebra.partition = problem.discretisation().partition_method();
  results.linear_algebra.rank_dofs = rank_dofs(problem.discretisation());
  return outcome;
}

template <int dim>
solvers::SecantOutcome
run_loop(const SolvePlan& plan, const io::Case& case_, const assembly::FormingProblem<dim>& problem,
         solvers::LinearSolver& solver, const IterationCallback& on_iteration,
         post::Results& results, const VectorX* start_velocity,
         assembly::FrictionMultipliers<dim>& multipliers) {
  solvers::SecantOutcome outcome;
  // Each loop is a driver (secant or Newton) over the problem's nonlinear
  // interface, its linear step swapped (Uzawa steps, the saddle point) or the
  // whole driver wrapped by exact friction's augmentation.
  solvers::FormingNonlinearProblem<dim> nonlinear(problem);
  solvers::TimedLinearStep linear(solver, results.timing);
  const auto take_augmented = [&](solvers::AugmentedOutcome<dim>&& augmented) {
    outcome = std::move(augmented.solve);
    multipliers = std::move(augmented.multipliers);
    results.augmentation = {augmented.augmentations, augmented.multiplier_change,
                            augmented.friction_residual, augmented.power_residual};
  };
  switch (plan.loop) {
  case solvers::LoopKind::AugmentedNewton:
    // Exact Coulomb friction by Newton, multipliers updated between its steps
    // (solvers/augmented_newton.hpp); with friction.stick = "exact" every step holds
    // the stuck nodes' u_T = 0 exactly (solvers/exact_stick.hpp).
    if (plan.shape.exact_stick) nonlinear.enable_exact_stick();
    take_augmented(solvers::augmented_newton(nonlinear, solver, case_.solver, on_iteration,
                                             results.timing, start_velocity));
    return outcome;
  case solvers::LoopKind::AugmentedSecant:
    // Exact friction, the paper's method (or a mixed formulation): the
    // augmentation around the secant iteration, an update per converged inner solve.
    take_augmented(solvers::augmented_lagrangian(nonlinear, solver, case_.solver, on_iteration,
                                                 results.timing));
    return outcome;
  case solvers::LoopKind::SaddlePointSecant: {
    // Taylor–Hood: a continuous pressure cannot be condensed; the saddle-point
    // system is indefinite (an LU back-end, solvers/capabilities.hpp).
    solvers::SaddlePointSolve<dim> saddle(nonlinear, linear);
    return solvers::secant_iteration(nonlinear, saddle, case_.solver, on_iteration, start_velocity);
  }
  case solvers::LoopKind::UzawaSecant: {
    solvers::SecantSolve uzawa(nonlinear, linear, /*uzawa_steps=*/true);
    return solvers::secant_iteration(nonlinear, uzawa, case_.solver, on_iteration);
  }
  case solvers::LoopKind::Newton:
    // The penalty problem (plane and axisymmetric) and the mixed one with its
    // pressure condensed at d > 0 (the condensation is linear in u).
    return solvers::newton_iteration(nonlinear, solver, case_.solver, on_iteration, results.timing,
                                     start_velocity);
  case solvers::LoopKind::Secant:
    return solvers::secant_iteration(nonlinear, solver, case_.solver, on_iteration, results.timing);
  }
  FF_ASSERT(false, "every loop kind is handled above");
  return {};
}

/// Everything after the mesh: problem, multipliers, coarse start (when the
/// mesh came from case_.mesh, so coarser levels of it can be made), the loop,
/// post-processing. Fills `simulation` except its mesh, which `mesh` lives in.
template <int dim>
void solve_on(const io::Case& case_, const mesh::Mesh<dim>& mesh, bool mesh_from_case,
              Simulation& simulation, const IterationCallback& on_iteration,
              bool estimate_condition, const VectorX* start_velocity);

/// solve_on, with an input error found by a back-end during the solve (a PETSc
/// option that nothing read: the solver knows the key, not the file) located where
/// the case set that key.
template <int dim>
void solve_located(const io::Case& case_, const mesh::Mesh<dim>& mesh, bool mesh_from_case,
                   Simulation& simulation, const IterationCallback& on_iteration,
                   bool estimate_condition, const VectorX* start_velocity = nullptr) {
  try {
    solve_on(case_, mesh, mesh_from_case, simulation, on_iteration, estimate_condition,
             start_velocity);
  } catch (const InputError& error) {
    const auto where = case_.key_locations.find(error.key);
    if (!error.file.empty()) throw;
    if (where == case_.key_locations.end())
      throw InputError(case_.source, 0, error.key, error.message, error.hint);
    throw InputError(where->second.file, where->second.line, error.key, error.message, error.hint);
  }
}

template <int dim>
void solve_on(const io::Case& case_, const mesh::Mesh<dim>& mesh, bool mesh_from_case,
              Simulation& simulation, const IterationCallback& on_iteration,
              bool estimate_condition, const VectorX* start_velocity) {
  post::Results& results = simulation.results;
  std::unique_ptr<assembly::FormingProblem<dim>> problem;
  {
    ScopedTimer timer(results.timing, "setup");
    problem = std::make_unique<assembly::FormingProblem<dim>>(mesh, problem_settings(case_));
  }
  // Mixed formulation and exact constraints (issue 5): pressures condensed cell
  // by cell keep the velocity system SPD, so CHOLMOD serves every formulation.
  // Exact friction (friction.regularization = "none") with d = 0 or d_N = 0 is
  // refused by the case validation: one multiplier loop at a time.
  std::unique_ptr<assembly::ConstraintMultipliers<dim>> constraint_multipliers;
  if (case_.formulation.type == assembly::FormulationType::Mixed || case_.penalty.d_n == 0) {
    constraint_multipliers = std::make_unique<assembly::ConstraintMultipliers<dim>>(
        mesh, case_.penalty, case_.formulation, problem->full_rule(), problem->n_contact_points(),
        problem->discretisation().axisymmetric());
    problem->attach_multipliers(constraint_multipliers.get());
  }
  const SolvePlan plan = make_solve_plan(case_);
  // Mesh sequencing (solver.coarse_levels) for the Newton loops and the discontinuous
  // saddle point's secant loop: start from the coarse solution. Exact friction's coarse
  // levels solve the Coulomb law with λ̂ = 0, i.e. stick penalty r (the multipliers live
  // at the fine Γ3 points only).
  std::optional<CoarseStart> coarse;
  if (plan.sequences_meshes() && mesh_from_case && !start_velocity) {
    coarse = coarse_start(case_, problem->discretisation(), results.timing);
    if (coarse) {
      results.coarse_iterations = coarse->iterations;
      results.coarse_mesh_sizes = coarse->mesh_sizes;
    }
  }
  assembly::FrictionMultipliers<dim> multipliers;
  solvers::SecantOutcome outcome;
  if (case_.thermal.enabled) {
    // Hot forming (app/thermal_coupling.hpp): the loop below, again at each coupling step,
    // with one solver whose symbolic analysis serves every step (the pattern is the same).
    const auto solver = solvers::reuse_analysis(plan_solver(plan, case_));
    io::Case inner = case_; // solver.tolerance set per coupling step (inexact staggering)
    const FlowSolve solve_flow = [&](const VectorX* start, Real tolerance) {
      inner.solver.tolerance = tolerance;
      return run_counted_loop(plan, inner, *problem, *solver, on_iteration, results,
                              start ? start : (coarse ? &coarse->velocity : start_velocity),
                              multipliers);
    };
    outcome = couple_thermal(case_, *problem, solve_flow, on_iteration, multipliers, results);
  } else {
    const auto solver = plan_solver(plan, case_);
    outcome = run_counted_loop(plan, case_, *problem, *solver, on_iteration, results,
                               coarse ? &coarse->velocity : start_velocity, multipliers);
  }
  results.method = plan.name(coarse.has_value());
  results.stop_reason = outcome.stop_reason;
  results.history = std::move(outcome.history);
  results.iterations = static_cast<int>(results.history.size());
  // Exact friction by Newton reports stick where the slip is below what δ resolves.
  const Real stick_speed = plan.loop == solvers::LoopKind::AugmentedNewton
                               ? case_.solver.tolerance * case_.process.speed
                               : 0.0;
  post::evaluate_results(*problem, outcome.velocity, results, &multipliers, stick_speed);
  if (results.thermal.enabled) results.fields.temperature = results.thermal.temperature;
  // The load's error bar (docs/error-estimation.md): one adjoint solve on the mesh refined once.
  results.load_error =
      load_error_of(case_, *problem, outcome.velocity, results.pressure.ram_reaction,
                    mesh_from_case, results.converged(), results.timing, on_iteration);
  results.fields.cell_load_error = results.load_error.cell_indicators;
  if (estimate_condition)
    simulation.reciprocal_condition = condition_at(*problem, outcome.velocity);
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

Simulation simulate(const io::Case& case_, const IterationCallback& on_iteration,
                    bool estimate_condition) {
  check_distributed(case_); // what a run on several ranks does not serve yet: exit 2
  if (case_.manufactured != physics::ManufacturedSolution::None)
    return simulate_manufactured(case_, on_iteration, estimate_condition);
  if (case_.adapt.enabled()) return simulate_adaptive(case_, on_iteration); // app/adaptive_run.cpp
  Simulation simulation;
  const auto start = Clock::now();
  {
    ScopedTimer timer(simulation.results.timing, "mesh");
    simulation.mesh = io::load_mesh(case_);
  }
  // The one dispatch on the dimension: the mesh source decided it.
  std::visit(
      [&](const auto& mesh) {
        solve_located(case_, mesh, true, simulation, on_iteration, estimate_condition);
      },
      simulation.mesh);
  add_total(simulation.results, start);
  return simulation;
}

template <int dim>
Simulation simulate_on(const io::Case& case_, mesh::Mesh<dim> mesh,
                       const IterationCallback& on_iteration, bool estimate_condition) {
  Simulation simulation;
  const auto start = Clock::now();
  simulation.mesh = std::move(mesh);
  // No mesh sequencing: its coarse levels would be re-made from case_.mesh,
  // which is not where this mesh came from.
  solve_located(case_, std::get<mesh::Mesh<dim>>(simulation.mesh), false, simulation, on_iteration,
                estimate_condition);
  add_total(simulation.results, start);
  return simulation;
}

template <int dim>
Simulation simulate_from(const io::Case& case_, mesh::Mesh<dim> mesh, const VectorX& start,
                         const IterationCallback& on_iteration) {
  Simulation simulation;
  const auto clock_start = Clock::now();
  simulation.mesh = std::move(mesh);
  solve_located(case_, std::get<mesh::Mesh<dim>>(simulation.mesh), false, simulation, on_iteration,
                false, &start);
  add_total(simulation.results, clock_start);
  return simulation;
}

template Simulation simulate_from<2>(const io::Case&, mesh::Mesh<2>, const VectorX&,
                                     const IterationCallback&);
template Simulation simulate_from<3>(const io::Case&, mesh::Mesh<3>, const VectorX&,
                                     const IterationCallback&);
template Real condition_at<2>(const assembly::FormingProblem<2>&, const VectorX&);
template Real condition_at<3>(const assembly::FormingProblem<3>&, const VectorX&);
template Simulation simulate_on<2>(const io::Case&, mesh::Mesh<2>, const IterationCallback&, bool);
template Simulation simulate_on<3>(const io::Case&, mesh::Mesh<3>, const IterationCallback&, bool);

} // namespace formflow::app
