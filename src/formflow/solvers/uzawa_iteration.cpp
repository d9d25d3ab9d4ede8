// SPDX-License-Identifier: MIT
// Secant steps around Uzawa multiplier updates that reuse one factorisation.
#include "formflow/solvers/uzawa_iteration.hpp"
#include "formflow/solvers/stop_rule.hpp"

#include "formflow/core/error.hpp"

#include <chrono>
#include <cmath>

namespace formflow::solvers {

namespace {


struct UzawaStep {
  std::optional<StopReason> stop;
  bool constraints_converged = false;
};

/// One secant step at the lagged velocity `w` (null: constant viscosity):
/// factorise K_r(w) once, then Uzawa steps until the multipliers settle.
template <int dim>
UzawaStep solve_with_multipliers(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                                 const VectorX* w, assembly::LinearSystem& system, bool analyse,
                                 VectorX& velocity, PhaseTimes& times) {
  assembly::ConstraintMultipliers<dim>& multipliers = *problem.multipliers();
  const assembly::Formulation& formulation = multipliers.formulation();
  UzawaStep result;
  for (int step = 0; step < formulation.uzawa_max_steps; ++step) {
    {
      ScopedTimer timer(times, "assembly");
      problem.assemble(w, system); // same matrix each step; the load −Bᵀλ changes
    }
    if (step == 0) {
      if (analyse) {
        ScopedTimer timer(times, "analysis");
        if (!solver.analyze(system.matrix))
          return {StopReason::SolverFailed, false};
      }
      ScopedTimer timer(times, "factorization");
      if (!solver.factorize(system.matrix))
        return {StopReason::SolverFailed, false};
    }
    VectorX free_velocity;
    {
      ScopedTimer timer(times, "solve");
      if (!solver.solve(system.rhs, free_velocity))
        return {StopReason::SolverFailed, false};
    }
    if (!free_velocity.allFinite())
      return {StopReason::NonFinite, false};
    velocity = problem.plan().expand(free_velocity, problem.constraints().values);
    std::vector<Real> normal_velocity;
    if (multipliers.is_exact_contact()) {
      const auto contact = problem.contact_state(velocity);
      for (const auto& point : contact)
        normal_velocity.push_back(point.normal_velocity);
    }
    const Real change = multipliers.update(velocity, normal_velocity);
    if (!std::isfinite(change))
      return {StopReason::NonFinite, false};
    if (change < formulation.uzawa_tolerance) {
      result.constraints_converged = true;
      break;
    }
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
  SecantOutcome outcome;
  assembly::LinearSystem system = problem.plan().make_system();
  outcome.velocity = problem.constraints().values;
  if (auto first =
          solve_with_multipliers(problem, solver, nullptr, system, true, outcome.velocity, times);
      first.stop) {
    outcome.stop_reason = *first.stop;
    return outcome;
  }
  for (int iteration = 1; iteration <= control.max_iterations; ++iteration) {
    const auto start = std::chrono::steady_clock::now();
    VectorX next;
    const UzawaStep step =
        solve_with_multipliers(problem, solver, &outcome.velocity, system, false, next, times);
    if (step.stop) {
      outcome.stop_reason = *step.stop;
      return outcome;
    }
    const Real change = (next - outcome.velocity).norm() / next.norm();
    IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    // Reaction of the last system solved, its pressure load included: K_c· u − (−Bᵀλ)_c.
    record.pressure = problem.driven_force(system, next) / problem.driven_height();
    record.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.velocity = std::move(next);
    outcome.history.push_back(record);
    if (on_iteration)
      on_iteration(record);
    if (const auto stop = stop_after_iteration(change, change, record.pressure,
                                             control.tolerance, step.constraints_converged)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
  }
  outcome.stop_reason = StopReason::MaxIterations;
  return outcome;
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
