// SPDX-License-Identifier: MIT
// The secant-modulus loop with its stop reasons.
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/lagged_iteration.hpp"

namespace formflow::solvers {

namespace {

/// Assembles K(w), factorises and solves; returns the full velocity or a stop reason.
template <int dim>
std::optional<StopReason>
solve_linearised(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                 const VectorX* w, assembly::LinearSystem& system, bool analyse, VectorX& velocity,
                 PhaseTimes& times, const assembly::FrictionMultipliers<dim>* multipliers) {
  {
    ScopedTimer timer(times, "assembly");
    problem.assemble(w, system, multipliers);
  }
  if (analyse) {
    ScopedTimer timer(times, "analysis");
    if (!solver.analyze(system.matrix)) return StopReason::SolverFailed;
  }
  {
    ScopedTimer timer(times, "factorization");
    if (!solver.factorize(system.matrix)) return StopReason::SolverFailed;
  }
  VectorX free_velocity;
  {
    ScopedTimer timer(times, "solve");
    if (!solver.solve(system.rhs, free_velocity)) return StopReason::SolverFailed;
  }
  if (!free_velocity.allFinite()) return StopReason::NonFinite;
  velocity = problem.plan().expand(free_velocity, problem.constraints().values);
  return std::nullopt;
}

} // namespace

template <int dim>
SecantOutcome
secant_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                 const IterationControl& control,
                 const std::function<void(const IterationRecord&)>& on_iteration, PhaseTimes& times,
                 const assembly::FrictionMultipliers<dim>* multipliers, const VectorX* start) {
  assembly::LinearSystem system = problem.plan().make_system();
  bool analysed = false; // the first solve analyses the pattern, warm start or not
  return run_lagged_iteration(
      problem, system, control, on_iteration, start, [&](const VectorX* w, VectorX& next) {
        const std::optional<StopReason> stop =
            solve_linearised(problem, solver, w, system, !analysed, next, times, multipliers);
        analysed = true;
        return LaggedStep{stop, true};
      });
}

template SecantOutcome secant_iteration<2>(const assembly::FormingProblem<2>&, LinearSolver&,
                                           const IterationControl&,
                                           const std::function<void(const IterationRecord&)>&,
                                           PhaseTimes&, const assembly::FrictionMultipliers<2>*,
                                           const VectorX*);
template SecantOutcome secant_iteration<3>(const assembly::FormingProblem<3>&, LinearSolver&,
                                           const IterationControl&,
                                           const std::function<void(const IterationRecord&)>&,
                                           PhaseTimes&, const assembly::FrictionMultipliers<3>*,
                                           const VectorX*);

} // namespace formflow::solvers
