// SPDX-License-Identifier: MIT
// The Newton loop: secant start, tangent steps with a line search, secant fallback.
#include "formflow/solvers/newton_iteration.hpp"
#include "formflow/solvers/stop_rule.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

namespace formflow::solvers {

namespace {

/// A relative change this large means the iterates run away, not converge (as in secant).
/// The line search stops once |δ·R(u + tδ)| ≤ this × |δ·R(u)| (a Wolfe-type curvature test).
constexpr Real line_search_slope_ratio = 0.5;
constexpr int max_line_search_steps = 8;

/// The free components of a full dof vector.
VectorX free_part(const assembly::ScatterPlan& plan, const VectorX& full) {
  VectorX free_values(plan.n_free());
  for (Index dof = 0; dof < plan.n_dofs(); ++dof)
    if (plan.free_index(dof) >= 0) free_values[plan.free_index(dof)] = full[dof];
  return free_values;
}

/// R_f(u) = K_ff(u) u_f − F_f(u): the residual of eq. (3.19) on the free dofs,
/// since a(u; u, v) and the friction form are K(u) applied to u itself.
VectorX residual(const assembly::LinearSystem& secant, const VectorX& free_velocity) {
  return secant.matrix.selfadjointView<Eigen::Lower>() * free_velocity - secant.rhs;
}

/// Working state shared by the steps of one solve.
template <int dim>
struct NewtonWork {
  const assembly::FormingProblem<dim>& problem;
  LinearSolver& solver;
  PhaseTimes& times;
  assembly::LinearSystem secant, tangent;
  assembly::NewtonDuals<dim> duals;  ///< empty = primal (the exact tangent)
  int factorizations = 0;
};

/// K(w) u = F (w = nullptr: constant viscosity): returns the full velocity, or a stop reason.
template <int dim>
std::optional<StopReason> secant_step(NewtonWork<dim>& work, const VectorX* w, VectorX& velocity) {
  {
    ScopedTimer timer(work.times, "assembly");
    work.problem.assemble(w, work.secant);
  }
  {
    ScopedTimer timer(work.times, "factorization");
    ++work.factorizations;
    if (!work.solver.factorize(work.secant.matrix)) return StopReason::SolverFailed;
  }
  VectorX free_velocity;
  {
    ScopedTimer timer(work.times, "solve");
    if (!work.solver.solve(work.secant.rhs, free_velocity)) return StopReason::SolverFailed;
  }
  if (!free_velocity.allFinite()) return StopReason::NonFinite;
  velocity = work.problem.plan().expand(free_velocity, work.problem.constraints().values);
  return std::nullopt;
}

/// δ·R(u + t δ) with τ_f frozen: the slope of the potential along δ at t.
/// Leaves the secant system of the trial point in work.secant.
template <int dim>
Real slope_at(NewtonWork<dim>& work, const VectorX& velocity, const VectorX& step, Real t,
              std::span<const Real> thresholds, const VectorX& free_step) {
  const VectorX trial = velocity + t * step;
  work.problem.assemble_newton(trial, thresholds, work.duals, work.secant, nullptr);
  return free_step.dot(residual(work.secant, free_part(work.problem.plan(), trial)));
}

/// One Newton step from `velocity`; std::nullopt when the tangent is not positive
/// definite or δ is no descent direction (the caller then takes a secant step).
/// On success work.secant holds K(uⁿ⁺¹) for the reaction force.
template <int dim>
std::optional<VectorX> newton_step(NewtonWork<dim>& work, const VectorX& velocity,
                                   Real& full_change) {
  const assembly::ScatterPlan& plan = work.problem.plan();
  const std::vector<Real> thresholds = work.problem.friction_thresholds(velocity);
  VectorX gradient;
  {
    ScopedTimer timer(work.times, "assembly");
    work.problem.assemble_newton(velocity, thresholds, work.duals, work.secant, &work.tangent);
    gradient = residual(work.secant, free_part(plan, velocity));
  }
  {
    ScopedTimer timer(work.times, "factorization");
    ++work.factorizations;
    if (!work.solver.factorize(work.tangent.matrix)) return std::nullopt;
  }
  VectorX free_step;
  {
    ScopedTimer timer(work.times, "solve");
    if (!work.solver.solve(-gradient, free_step) || !free_step.allFinite()) return std::nullopt;
  }
  const Real slope0 = free_step.dot(gradient);  // = −δᵀJδ < 0 for an SPD tangent
  if (!(slope0 < 0)) return std::nullopt;
  const VectorX step = plan.expand(free_step, VectorX::Zero(plan.n_dofs()));

  // Line search on the convex potential along δ: find t with |slope(t)| small.
  // Full step if the potential still decreases at t = 1; otherwise regula falsi
  // (Illinois variant) on the bracket [0, 1] where the slope changes sign.
  ScopedTimer timer(work.times, "line search");
  Real t = 1.0, slope = slope_at(work, velocity, step, t, thresholds, free_step);
  Real low = 0.0, slope_low = slope0, high = 1.0, slope_high = slope;
  for (int k = 0; k < max_line_search_steps; ++k) {
    if (slope <= 0 && k == 0) break;
    if (std::abs(slope) <= line_search_slope_ratio * std::abs(slope0)) break;
    t = low - slope_low * (high - low) / (slope_high - slope_low);
    slope = slope_at(work, velocity, step, t, thresholds, free_step);
    if (slope > 0) {
      high = t, slope_high = slope;
      slope_low *= 0.5;
    } else {
      low = t, slope_low = slope;
      slope_high *= 0.5;
    }
  }
  VectorX next = velocity + t * step;
  {
    ScopedTimer dual_timer(work.times, "dual update");
    work.problem.update_duals(velocity, step, next, work.duals);
  }
  full_change = step.norm() / next.norm();
  return next;
}

}  // namespace

template <int dim>
SecantOutcome newton_iteration(const assembly::FormingProblem<dim>& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const std::function<void(const IterationRecord&)>& on_iteration,
                               PhaseTimes& times) {
  SecantOutcome outcome;
  NewtonWork<dim> work{problem, solver, times, problem.plan().make_system(),
                       problem.plan().make_system(), {}, 0};
  outcome.velocity = problem.constraints().values;
  {
    problem.assemble(nullptr, work.secant);
    ScopedTimer timer(times, "analysis");
    if (!solver.analyze(work.secant.matrix)) {
      outcome.stop_reason = StopReason::SolverFailed;
      return outcome;
    }
  }
  if (auto stop = secant_step(work, nullptr, outcome.velocity)) {
    outcome.stop_reason = *stop;
    return outcome;
  }
  // `step_change` is the change actually made (it gates Newton and detects
  // divergence); the stop test uses, for a Newton step, the larger of it and the
  // undamped Newton correction, so that a short damped step is never taken for
  // convergence.
  Real step_change = std::numeric_limits<Real>::infinity();
  for (int iteration = 1; iteration <= control.max_iterations; ++iteration) {
    const auto start = std::chrono::steady_clock::now();
    std::optional<VectorX> next;
    Real full_change = 0.0;
    if (step_change <= control.newton_start) next = newton_step(work, outcome.velocity, full_change);
    if (!next) {
      next.emplace();
      if (auto stop = secant_step(work, &outcome.velocity, *next)) {
        outcome.stop_reason = *stop;
        return outcome;
      }
      work.duals.clear();  // after a secant step the dual restarts from w = ν ė
    }
    step_change = (*next - outcome.velocity).norm() / next->norm();
    const Real change = std::max(step_change, full_change);
    IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    record.pressure = problem.driven_force(work.secant, *next) / problem.driven_height();
    record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.velocity = std::move(*next);
    outcome.history.push_back(record);
    if (on_iteration) on_iteration(record);
    if (const auto stop = stop_after_iteration(change, step_change, record.pressure,
                                             control.tolerance)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
  }
  outcome.stop_reason = StopReason::MaxIterations;
  return outcome;
}

template SecantOutcome newton_iteration<2>(const assembly::FormingProblem<2>&, LinearSolver&,
                                           const IterationControl&,
                                           const std::function<void(const IterationRecord&)>&,
                                           PhaseTimes&);
template SecantOutcome newton_iteration<3>(const assembly::FormingProblem<3>&, LinearSolver&,
                                           const IterationControl&,
                                           const std::function<void(const IterationRecord&)>&,
                                           PhaseTimes&);

}  // namespace formflow::solvers
