// SPDX-License-Identifier: MIT
// The Newton loop: secant start, tangent steps with a line search, secant fallback.
#include "formflow/solvers/newton_iteration.hpp"
#include "formflow/solvers/coupled_tangent_solve.hpp"
#include "formflow/solvers/exact_stick.hpp"
#include "formflow/solvers/stop_rule.hpp"
#include "formflow/solvers/timed_linear_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

namespace formflow::solvers {

namespace {

/// A relative change this large means the iterates run away, not converge (as in secant).
/// The line search stops once |δ·R(u + tδ)| ≤ this × |δ·R(u)| (a Wolfe-type curvature test).
constexpr Real line_search_slope_ratio = 0.5;
constexpr int max_line_search_steps = 8;
/// How far past a slip-reversal kink the step goes (relative): the node's slip is then
/// −1e-3 of what it was, so r |u_T| ≪ 2 τ_f and its trial falls inside the Coulomb disk.
constexpr Real kink_overshoot = 1e-3;

/// GMRES on the unsymmetric Jacobian: the inexact-Newton forcing term η (relative
/// preconditioned residual) is the last relative change clamped to [1e-3, 1e-2]:
/// early steps need little accuracy, and on fine meshes the tail contracts by only
/// ≈ 0.5 per step (the dual caps), so a linear error below 1e-3 of the step is
/// invisible there while each GMRES iteration costs a pair of triangular solves.
/// Measured: η = 1e-2 and 1e-6 give the same Newton counts on mesh II, h = 0.5
/// and h = 0.125 (μ = 0.1); GMRES then takes 2–4 iterations per step. Past the
/// cap the last GMRES iterate is used (rejected below if it is no descent
/// direction); the cap also bounds Eigen's Krylov basis (n × (cap + 1) doubles).
constexpr Real max_forcing = 1e-2, min_forcing = 1e-3;
constexpr int max_krylov_iterations = 20;

/// Working state shared by the steps of one solve.
struct NewtonWork {
  NonlinearProblem& problem;
  TimedLinearStep linear;
  assembly::LinearSystem secant, tangent;
  VectorX force;                    ///< internal force K(u)u at the last residual evaluation
  std::unique_ptr<DualState> duals; ///< empty = primal (the exact tangent)
  Real forcing = max_forcing;       ///< GMRES tolerance η of the next Newton step
  Real tolerance = 0.0;             ///< δ of the stop rule
  /// tangent, coupling and force were assembled at the current iterate with the
  /// current duals (by the previous step's line search): no assembly needed.
  bool tangent_ready = false;
  /// The tangent condensed onto the step's constraints (solvers/exact_stick.hpp).
  assembly::SparseMatrix condensed = {};
};

/// K(w) u = F (w = nullptr: constant viscosity): returns the full velocity, or a stop reason.
std::optional<StopReason> secant_step(NewtonWork& work, const VectorX* w, VectorX& velocity) {
  {
    ScopedTimer timer(work.linear.times(), "assembly");
    work.problem.assemble_secant(w, work.secant);
  }
  VectorX free_velocity;
  if (const auto stop = work.linear(work.secant.matrix, work.secant.rhs, free_velocity))
    return stop;
  velocity = work.problem.plan().expand(free_velocity, work.problem.prescribed_values());
  return std::nullopt;
}

/// δ·R(u + t δ), τ_f at the trial point (the residual the Jacobian differentiates).
/// Leaves the internal force of the trial point in work.force (no matrix is built).
Real slope_at(NewtonWork& work, const VectorX& velocity, const VectorX& step, Real t,
              const VectorX& free_step) {
  const VectorX trial = velocity + t * step;
  work.problem.assemble_newton(trial, *work.duals, work.force, nullptr);
  return work.problem.dot(free_step, work.problem.plan().free_values(work.force));
}

/// One Newton step from `velocity`; std::nullopt when the tangent is not positive
/// definite or δ is no descent direction (the caller then takes a secant step).
/// On success work.force holds the internal force at uⁿ⁺¹ (for the reaction).
std::optional<VectorX> newton_step(NewtonWork& work, const VectorX& velocity, Real& full_change) {
  const assembly::ScatterPlan& plan = work.problem.plan();
  if (!work.tangent_ready) {
    ScopedTimer timer(work.linear.times(), "assembly");
    work.problem.assemble_newton(velocity, *work.duals, work.force, &work.tangent);
  }
  work.tangent_ready = false;
  const VectorX gradient = plan.free_values(work.force);
  // Exact constraints on the step (exact friction's stuck nodes): δ = g + z, z = P z,
  // solved on the condensed tangent (solvers/exact_stick.hpp). One rank only: the
  // condensation of a rank's share of T is not its share of the condensed matrix (exact
  // stick is refused on several ranks, app/distributed_run.cpp).
  std::vector<StepConstraint> constraints = work.problem.step_constraints(velocity);
  const bool constrained = !constraints.empty();
  std::optional<StepCondensation> condensation;
  VectorX particular, rhs = -gradient;
  const assembly::SparseMatrix* matrix = &work.tangent.matrix;
  if (constrained) {
    condensation.emplace(std::move(constraints), plan.n_free());
    condensation->condense(work.tangent.matrix, work.condensed);
    matrix = &work.condensed;
    particular = condensation->particular();
    VectorX product = work.tangent.matrix.selfadjointView<Eigen::Lower>() * particular;
    if (work.problem.has_coupling()) work.problem.apply_coupling(particular, product);
    rhs = -condensation->project(gradient + product);
  }
  if (work.linear.factorize(*matrix)) return std::nullopt;
  VectorX free_step;
  // The right-hand side is whole on every rank of a distributed run (the internal force
  // is summed over the ranks; the tangent is each rank's share of the matrix).
  if (!work.problem.has_coupling()) {
    if (work.linear.solve_whole(rhs, free_step)) return std::nullopt;
  } else {
    // The full-ε̇ form: J = T + N, N unsymmetric; T's factor preconditions GMRES.
    ScopedTimer timer(work.linear.times(), "krylov");
    const CouplingProduct coupling = [&](const VectorX& x, VectorX& y) {
      if (!constrained) return work.problem.apply_coupling(x, y);
      VectorX projected = VectorX::Zero(x.size());
      work.problem.apply_coupling(condensation->project(x), projected);
      y += condensation->project(projected);
    };
    const ShareSum add_up_shares = [&](VectorX& values) { work.problem.add_up_shares(values); };
    // A distributed run's vectors are ghosted: GMRES then takes its inner products over
    // the ranks' owned entries (one rank: Eigen's GMRES on whole vectors).
    GhostedDot dot;
    if (work.problem.ghosted())
      dot = [&](const VectorX& a, const VectorX& b) { return work.problem.dot(a, b); };
    const KrylovOutcome krylov =
        solve_coupled_tangent(*matrix, coupling, work.linear.solver(), rhs, free_step, work.forcing,
                              max_krylov_iterations, add_up_shares, dot);
    work.linear.times().count("krylov iterations", krylov.iterations);
    if (!std::isfinite(work.problem.norm(free_step))) return std::nullopt;
  }
  // The line search runs along the unconstrained part z (its slope sees no stuck
  // tangential row, whose balance is the constraint's multiplier, set after the step).
  VectorX direction = free_step;
  std::vector<Real> reactions;
  if (constrained) {
    direction = condensation->project(free_step);
    free_step = particular + direction;
    // c_k·(R + J δ): what each constraint supplies for the full step.
    VectorX balance = work.tangent.matrix.selfadjointView<Eigen::Lower>() * free_step;
    if (work.problem.has_coupling()) work.problem.apply_coupling(free_step, balance);
    reactions = condensation->components(gradient + balance);
  }
  const Real slope0 =
      work.problem.dot(direction, gradient); // ≈ −δᵀJδ < 0 where J's symmetric part is SPD
  if (!(slope0 < 0) && !constrained) return std::nullopt;
  const VectorX step = plan.expand(free_step, VectorX::Zero(plan.n_dofs()));
  if (constrained && !(slope0 < 0)) {
    // No descent left along z (the stick targets dominate the step): the full
    // semismooth step, whose constraints hold exactly.
    VectorX next = velocity + step;
    work.problem.update_duals(velocity, step, next, *work.duals);
    work.problem.constrained_step_taken(reactions, 1.0);
    slope_at(work, next, step, 0.0, direction); // the internal force at uⁿ⁺¹
    full_change = work.problem.norm(step) / work.problem.norm(next);
    return next;
  }

  // Line search along δ on the slope δ·R(u + tδ) (the derivative of the potential
  // where there is one: deviatoric form, frozen τ_f): find t with |slope(t)| small.
  // Full step if the slope is still negative at t = 1 (or small); otherwise regula
  // falsi (Illinois variant) on the bracket [0, 1] where the slope changes sign.
  // The slope at t = 1 comes with the next step's tangent (duals updated for t = 1)
  // in one cell loop, so an accepted full step costs no separate residual pass
  // (measured: t = 1 is taken in every step of the paper's cases). The residual
  // is evaluated alone for a step small enough to end the iteration, and when an
  // outer loop updates exact friction's multipliers after every iteration (the
  // tangent would be assembled with the old ones and thrown away).
  const auto acceptable = [&](Real slope, int k) {
    return (slope <= 0 && k == 0) || std::abs(slope) <= line_search_slope_ratio * std::abs(slope0);
  };
  const bool look_ahead =
      !constrained && !work.problem.changes_after_iteration() &&
      work.problem.norm(step) / work.problem.norm(velocity + step) >= work.tolerance;
  Real t = 1.0, slope = 0.0;
  if (look_ahead) {
    const VectorX trial = velocity + step;
    std::unique_ptr<DualState> trial_duals = work.duals->clone();
    {
      ScopedTimer dual_timer(work.linear.times(), "dual update");
      work.problem.update_duals(velocity, step, trial, *trial_duals);
    }
    ScopedTimer timer(work.linear.times(), "assembly");
    work.problem.assemble_newton(trial, *trial_duals, work.force, &work.tangent);
    slope = work.problem.dot(free_step, plan.free_values(work.force));
    if (acceptable(slope, 0)) {
      work.duals = std::move(trial_duals);
      work.tangent_ready = true;
      full_change = work.problem.norm(step) / work.problem.norm(trial);
      return trial;
    }
  }
  ScopedTimer timer(work.linear.times(), "line search");
  if (!look_ahead) slope = slope_at(work, velocity, step, t, direction);
  Real low = 0.0, slope_low = slope0, high = 1.0, slope_high = slope;
  for (int k = 0; k < max_line_search_steps && !acceptable(slope, k); ++k) {
    t = low - slope_low * (high - low) / (slope_high - slope_low);
    slope = slope_at(work, velocity, step, t, direction);
    if (slope > 0) {
      high = t, slope_high = slope;
      slope_low *= 0.5;
    } else {
      low = t, slope_low = slope;
      slope_high *= 0.5;
    }
  }
  if (constrained && !acceptable(slope, max_line_search_steps)) {
    // No acceptable t on [0, 1]: the slope jumps where a slipping node's slip would
    // reverse along the step (its friction force flips by 2 τ_f). Stopping short of
    // that kink leaves the node slipping, a little less each iteration: a linear tail
    // (measured 0.885 per iteration, Q1 axisymmetric, sliding, h = 0.5, μ = 0.2). Just
    // past the kink the node's trial λ̂ + r u_T lies inside the disk: the active set
    // catches it as stuck and the next step holds it exactly.
    const Real kink = work.problem.slip_reversal(velocity, step);
    if (kink <= 1.0 && kink >= 0.5 * t) {
      t = std::min(1.0, kink * (1.0 + kink_overshoot));
      slope = slope_at(work, velocity, step, t, direction);
    }
  }
  VectorX next = velocity + t * step;
  {
    ScopedTimer dual_timer(work.linear.times(), "dual update");
    work.problem.update_duals(velocity, step, next, *work.duals);
  }
  if (constrained) work.problem.constrained_step_taken(reactions, t);
  full_change = work.problem.norm(step) / work.problem.norm(next);
  return next;
}

} // namespace

SecantOutcome newton_iteration(NonlinearProblem& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const IterationObserver& on_iteration, PhaseTimes& times,
                               const VectorX* initial) {
  SecantOutcome outcome;
  NewtonWork work{problem,
                  TimedLinearStep(solver, times),
                  problem.plan().make_system(),
                  problem.plan().make_system(),
                  {},
                  problem.make_duals()};
  work.tolerance = control.tolerance;
  outcome.velocity = problem.prescribed_values();
  // The pattern alone (work.secant is still the zeroed system): no assembly here.
  if (const auto stop = work.linear.analyse_once(work.secant.matrix)) {
    outcome.stop_reason = *stop;
    return outcome;
  }
  if (initial) {
    outcome.velocity =
        problem.plan().expand(problem.plan().free_values(*initial), problem.prescribed_values());
  } else if (auto stop = secant_step(work, nullptr, outcome.velocity)) {
    outcome.stop_reason = *stop;
    return outcome;
  }
  // `step_change` is the change actually made (it gates Newton and detects
  // divergence); the stop test uses, for a Newton step, the larger of it and the
  // undamped Newton correction, so that a short damped step is never taken for
  // convergence.
  // The first iteration is already a Newton step: from the constant-viscosity
  // solution, with the stress that solve balanced as the dual (secant_duals), the
  // tangent is stiff where that stress is below yield, so the step cannot blow
  // the near-rigid zones apart as the primal tangent (α-soft along ė) does.
  // From a given first iterate (a coarse solution) the same dual: ν(initial_rate) ė.
  problem.secant_duals(nullptr, outcome.velocity, *work.duals);
  Real step_change = 0.0;
  for (int iteration = 1; iteration <= control.max_iterations; ++iteration) {
    const auto start = std::chrono::steady_clock::now();
    std::optional<VectorX> next;
    Real full_change = 0.0;
    if (step_change <= control.newton_start)
      next = newton_step(work, outcome.velocity, full_change);
    const bool newton = next.has_value();
    if (!next) {
      next.emplace();
      if (auto stop = secant_step(work, &outcome.velocity, *next)) {
        outcome.stop_reason = *stop;
        return outcome;
      }
      // After a secant step the duals restart from the stress it balanced (not
      // the primal w = ν ė, whose tangent is α-soft along ė in near-rigid zones).
      problem.secant_duals(&outcome.velocity, *next, *work.duals);
      work.tangent_ready = false;
    }
    step_change = problem.norm(*next - outcome.velocity) / problem.norm(*next);
    const Real change = std::max(step_change, full_change);
    work.forcing = std::clamp(change, min_forcing, max_forcing);
    IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    record.pressure = (newton ? problem.internal_driven_force(work.force)
                              : problem.driven_force(work.secant, *next)) /
                      problem.driven_height();
    record.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.velocity = std::move(*next);
    outcome.history.push_back(record);
    if (on_iteration) on_iteration(record);
    const auto own = stop_after_iteration(change, step_change, record.pressure, control.tolerance);
    const AfterIteration after =
        problem.after_iteration({iteration, &outcome.velocity, own == StopReason::Converged, change,
                                 newton ? &work.force : nullptr});
    if (const auto stop = stop_with_hook(own, after)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
  }
  outcome.stop_reason = StopReason::MaxIterations;
  return outcome;
}

} // namespace formflow::solvers
