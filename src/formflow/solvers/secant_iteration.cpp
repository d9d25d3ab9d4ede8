// SPDX-License-Identifier: MIT
// The secant-modulus loop with its stop reasons.
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/stop_rule.hpp"

#include <chrono>
#include <cmath>

namespace formflow::solvers {

namespace {

/// A relative change this large means the iterates run away, not converge.

/// Assembles K(w), factorises and solves; returns the full velocity or a stop reason.
template <int dim>
std::optional<StopReason> solve_linearised(const assembly::FormingProblem<dim>& problem,
                                           LinearSolver& solver, const VectorX* w,
                                           assembly::LinearSystem& system, bool analyse,
                                           VectorX& velocity, PhaseTimes& times,
                                           const assembly::FrictionMultipliers<dim>* multipliers) {
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

}  // namespace

template <int dim>
SecantOutcome secant_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const std::function<void(const IterationRecord&)>& on_iteration,
                               PhaseTimes& times,
                               const assembly::FrictionMultipliers<dim>* multipliers,
                               const VectorX* start) {
  SecantOutcome outcome;
  assembly::LinearSystem system = problem.plan().make_system();
  outcome.velocity = problem.constraints().values;  // u = 0 except prescribed values
  bool analysed = false;
  if (start) {
    outcome.velocity = *start;
  } else {
    if (auto stop = solve_linearised(problem, solver, nullptr, system, true, outcome.velocity,
                                     times, multipliers)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
    analysed = true;
  }
  for (int iteration = 1; iteration <= control.max_iterations; ++iteration) {
    const auto start_time = std::chrono::steady_clock::now();
    VectorX next;
    if (auto stop = solve_linearised(problem, solver, &outcome.velocity, system, !analysed, next,
                                     times, multipliers)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
    analysed = true;
    const Real change = (next - outcome.velocity).norm() / next.norm();
    IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    // The reaction of the linear system just solved: K_c·(uⁿ) uⁿ⁺¹.
    record.pressure = problem.driven_force(system, next) / problem.driven_height();
    record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    outcome.velocity = std::move(next);
    outcome.history.push_back(record);
    if (on_iteration) on_iteration(record);
    if (const auto stop = stop_after_iteration(change, change, record.pressure,
                                             control.tolerance)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
  }
  outcome.stop_reason = StopReason::MaxIterations;
  return outcome;
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

}  // namespace formflow::solvers
