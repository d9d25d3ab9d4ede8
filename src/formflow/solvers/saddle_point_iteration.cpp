// SPDX-License-Identifier: MIT
// Secant steps around a global saddle-point solve (continuous pressure).
#include "formflow/solvers/saddle_point_iteration.hpp"

#include "formflow/assembly/saddle_point_system.hpp"
#include "formflow/core/error.hpp"
#include "formflow/solvers/lagged_iteration.hpp"
#include "formflow/solvers/uzawa_update.hpp"

namespace formflow::solvers {

namespace {

/// One secant step at the lagged velocity `w` (null: constant viscosity):
/// factorise the saddle-point matrix once, solve for (u, δp), and with exact
/// contact repeat the solve after each multiplier update until they settle.
template <int dim>
LaggedStep solve_saddle_point(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                              assembly::SaddlePointSystem<dim>& saddle, const VectorX* w,
                              assembly::LinearSystem& system, bool analyse, VectorX& velocity,
                              PhaseTimes& times) {
  assembly::ConstraintMultipliers<dim>& multipliers = *problem.multipliers();
  const assembly::Formulation& formulation = multipliers.formulation();
  const int max_steps = multipliers.is_exact_contact() ? formulation.uzawa_max_steps : 1;
  LaggedStep result{std::nullopt, false};
  UzawaSettling settling(formulation.uzawa_tolerance);
  for (int step = 0; step < max_steps; ++step) {
    {
      ScopedTimer timer(times, "assembly");
      problem.assemble(w, system); // same matrix each step; the loads −Bᵀp, −λ_N v_N change
    }
    if (step == 0) {
      saddle.fill_matrix(system);
      if (analyse) {
        ScopedTimer timer(times, "analysis");
        if (!solver.analyze(saddle.matrix())) return {StopReason::SolverFailed, false};
      }
      ScopedTimer timer(times, "factorization");
      if (!solver.factorize(saddle.matrix())) return {StopReason::SolverFailed, false};
    }
    const VectorX& pressure = multipliers.global_pressure();
    VectorX solution;
    {
      ScopedTimer timer(times, "solve");
      if (!solver.solve(saddle.rhs(system, pressure), solution))
        return {StopReason::SolverFailed, false};
    }
    if (!solution.allFinite()) return {StopReason::NonFinite, false};
    velocity =
        problem.plan().expand(solution.head(saddle.n_velocity()), problem.constraints().values);
    VectorX next_pressure = pressure + solution.tail(saddle.n_pressure());
    saddle.fix_pressure_level(next_pressure);
    // The reaction read from `system` must include the new pressure's load.
    saddle.add_pressure_load(next_pressure - pressure, system);
    multipliers.set_global_pressure(std::move(next_pressure));
    if (!multipliers.is_exact_contact()) {
      result.constraints_converged = true;
      break;
    }
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
saddle_point_secant_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                              const IterationControl& control,
                              const std::function<void(const IterationRecord&)>& on_iteration,
                              PhaseTimes& times) {
  FF_ASSERT(problem.multipliers() && problem.multipliers()->has_global_pressure(),
            "a saddle-point solve needs a global pressure");
  assembly::LinearSystem system = problem.plan().make_system();
  std::optional<assembly::SaddlePointSystem<dim>> saddle;
  {
    ScopedTimer timer(times, "setup");
    saddle.emplace(problem, *problem.multipliers(), system);
  }
  bool analyse = true; // the first solve analyses the pattern
  return run_lagged_iteration(
      problem, system, control, on_iteration, nullptr, [&](const VectorX* w, VectorX& next) {
        const LaggedStep step =
            solve_saddle_point(problem, solver, *saddle, w, system, analyse, next, times);
        analyse = false;
        return step;
      });
}

template SecantOutcome
saddle_point_secant_iteration<2>(const assembly::FormingProblem<2>&, LinearSolver&,
                                 const IterationControl&,
                                 const std::function<void(const IterationRecord&)>&, PhaseTimes&);
template SecantOutcome
saddle_point_secant_iteration<3>(const assembly::FormingProblem<3>&, LinearSolver&,
                                 const IterationControl&,
                                 const std::function<void(const IterationRecord&)>&, PhaseTimes&);

} // namespace formflow::solvers
