// SPDX-License-Identifier: MIT
// The loop stage: the plan's nonlinear loop on the solve's problem, the innermost stage.
#include "formflow/app/stages/stage.hpp"

#include "formflow/core/error.hpp"
#include "formflow/solvers/augmented_lagrangian.hpp"
#include "formflow/solvers/augmented_newton.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/newton_iteration.hpp"
#include "formflow/solvers/saddle_point_iteration.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <memory>

namespace formflow::app {

namespace {

/// Runs the nonlinear loop the plan chose on `problem` from `start_velocity`
/// (nullptr: the loop's own start) with the iteration control `control`; exact
/// friction's final multipliers go to `multipliers`.
template <int dim>
solvers::SecantOutcome
run_loop(const SolvePlan& plan, const solvers::IterationControl& control,
         const assembly::FormingProblem<dim>& problem, solvers::LinearSolver& solver,
         const IterationCallback& on_iteration, post::Results& results,
         const VectorX* start_velocity, assembly::FrictionMultipliers<dim>& multipliers);

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

/// The loop of the plan with `solver`; the linear algebra's record in `results` (the
/// Krylov count is the solver's running total: every loop that used it).
template <int dim>
solvers::SecantOutcome
run_counted_loop(const SolvePlan& plan, const solvers::IterationControl& control,
                 const assembly::FormingProblem<dim>& problem, solvers::LinearSolver& solver,
                 const IterationCallback& on_iteration, post::Results& results,
                 const VectorX* start_velocity, assembly::FrictionMultipliers<dim>& multipliers) {
  KrylovCounter counter(solver, on_iteration);
  solvers::SecantOutcome outcome = run_loop(plan, control, problem, solver, counter.observer(),
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
  results.linear_algebra.ranks = problem.discretisation().distribution().size;
  results.cell_ranks = problem.discretisation().cell_ranks();
  results.linear_algebra.partition = problem.discretisation().partition_method();
  results.linear_algebra.rank_dofs = rank_dofs(problem.discretisation());
  return outcome;
}

template <int dim>
solvers::SecantOutcome
run_loop(const SolvePlan& plan, const solvers::IterationControl& control,
         const assembly::FormingProblem<dim>& problem, solvers::LinearSolver& solver,
         const IterationCallback& on_iteration, post::Results& results,
         const VectorX* start_velocity, assembly::FrictionMultipliers<dim>& multipliers) {
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
    take_augmented(solvers::augmented_newton(nonlinear, solver, control, on_iteration,
                                             results.timing, start_velocity));
    return outcome;
  case solvers::LoopKind::AugmentedSecant:
    // Exact friction, the paper's method (or a mixed formulation): the
    // augmentation around the secant iteration, an update per converged inner solve.
    take_augmented(
        solvers::augmented_lagrangian(nonlinear, solver, control, on_iteration, results.timing));
    return outcome;
  case solvers::LoopKind::SaddlePointSecant: {
    // Taylor–Hood: a continuous pressure cannot be condensed; the saddle-point
    // system is indefinite (an LU back-end, solvers/capabilities.hpp).
    solvers::SaddlePointSolve<dim> saddle(nonlinear, linear);
    return solvers::secant_iteration(nonlinear, saddle, control, on_iteration, start_velocity);
  }
  case solvers::LoopKind::UzawaSecant: {
    solvers::SecantSolve uzawa(nonlinear, linear, /*uzawa_steps=*/true);
    return solvers::secant_iteration(nonlinear, uzawa, control, on_iteration);
  }
  case solvers::LoopKind::Newton:
    // The penalty problem (plane and axisymmetric) and the mixed one with its
    // pressure condensed at d > 0 (the condensation is linear in u).
    return solvers::newton_iteration(nonlinear, solver, control, on_iteration, results.timing,
                                     start_velocity);
  case solvers::LoopKind::Secant:
    return solvers::secant_iteration(nonlinear, solver, control, on_iteration, results.timing);
  }
  FF_ASSERT(false, "every loop kind is handled above");
  return {};
}

/// The plan's loop, the end of every forming chain: it owns the loop's records to the
/// monitor and summary.json's `linear_algebra`; its stop rule is the loop's
/// (solver.tolerance, solver.max_iterations: the driver's StopReason).
class LoopStage final : public StageOf<LoopStage> {
public:
  std::string_view name() const override { return "nonlinear loop"; }

  template <int dim> void run_on(SolveState<dim>& state, const StageChain&) const {
    const SolvePlan& plan = state.run_plan().solve;
    FF_ASSERT(state.problem, "the solve stage builds the problem before the loop");
    std::shared_ptr<solvers::LinearSolver> solver = state.solver;
    if (!solver)
      solver = solvers::make_linear_solver(plan.linear, solvers::loop_storage(plan.loop),
                                           state.control.petsc_options);
    state.outcome =
        run_counted_loop(plan, state.control, *state.problem, *solver, state.on_iteration,
                         state.results(), state.start, state.multipliers);
  }
};

} // namespace

const Stage& loop_stage() {
  static const LoopStage stage;
  return stage;
}

} // namespace formflow::app
