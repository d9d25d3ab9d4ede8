// SPDX-License-Identifier: MIT
// Secant steps around Uzawa multiplier updates that reuse one factorisation.
#include "formflow/solvers/uzawa_iteration.hpp"
#include "formflow/solvers/lagged_iteration.hpp"
#include "formflow/solvers/uzawa_update.hpp"

#include "formflow/core/error.hpp"

namespace formflow::solvers {

namespace {

/// One secant step at the lagged velocity `w` (null: constant viscosity):
/// factorise K_r(w) once, then Uzawa steps until the multipliers settle.
template <int dim>
LaggedStep solve_with_multipliers(const assembly::FormingProblem<dim>& problem,
                                  LinearSolver& solver, const VectorX* w,
                                  assembly::LinearSystem& system, bool analyse, VectorX& velocity,
                                  PhaseTimes& times) {
  assembly::ConstraintMultipliers<dim>& multipliers = *problem.multipliers();
  const assembly::Formulation& formulation = multipliers.formulation();
  LaggedStep result{std::nullopt, false};
  UzawaSettling settling(formulation.uzawa_tolerance);
  for (int step = 0; step < formulation.uzawa_max_steps; ++step) {
    {
      ScopedTimer timer(times, "assembly");
      problem.assemble(w, system); // same matrix each step; the load −Bᵀλ changes
    }
    if (step == 0) {
      if (analyse) {
        ScopedTimer timer(times, "analysis");
        if (!solver.analyze(system.matrix)) return {StopReason::SolverFailed, false};
      }
      ScopedTimer timer(times, "factorization");
      if (!solver.factorize(system.matrix)) return {StopReason::SolverFailed, false};
    }
    VectorX free_velocity;
    {
      ScopedTimer timer(times, "solve");
      if (!solver.solve(system.rhs, free_velocity)) return {StopReason::SolverFailed, false};
    }
    if (!free_velocity.allFinite()) return {StopReason::NonFinite, false};
    velocity = problem.plan().expand(free_velocity, problem.constraints().values);
    if (const auto stop =
            update_multipliers(problem, velocity, settling, result.constraints_converged))
      return {stop, false};
    if (result.constraints_converged) break;
  }
  return result;
}

} // namespace

template <int dim>
SecantOutcome
uzawa_secant_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                       const IterationControl& control,
                       const std::function<void(const IterationRecord&)>& on_iteration,
                       PhaseTimes& times) {
  FF_ASSERT(problem.multipliers() && problem.multipliers()->needs_uzawa(),
            "Uzawa steps need exact-constraint multipliers");
  assembly::LinearSystem system = problem.plan().make_system();
  bool analyse = true; // the first solve analyses the pattern
  return run_lagged_iteration(
      problem, system, control, on_iteration, nullptr, [&](const VectorX* w, VectorX& next) {
        const LaggedStep step =
            solve_with_multipliers(problem, solver, w, system, analyse, next, times);
        analyse = false;
        return step;
      });
}

template SecantOutcome uzawa_secant_iteration<2>(const assembly::FormingProblem<2>&, LinearSolver&,
                                                 const IterationControl&,
                                                 const std::function<void(const IterationRecord&)>&,
                                                 PhaseTimes&);
template SecantOutcome uzawa_secant_iteration<3>(const assembly::FormingProblem<3>&, LinearSolver&,
                                                 const IterationControl&,
                                                 const std::function<void(const IterationRecord&)>&,
                                                 PhaseTimes&);

} // namespace formflow::solvers
