// SPDX-License-Identifier: MIT
// The outer Kachanov loop shared by the plain, Uzawa and saddle-point secant
// iterations: they differ only in how one linear problem with the lagged
// viscosity is solved (a LaggedSolve), not in how iterations are recorded,
// monitored and stopped.
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/anderson_acceleration.hpp"
#include "formflow/solvers/stop_rule.hpp"
#include "formflow/solvers/uzawa_update.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <chrono>

namespace formflow::solvers {

SecantSolve::SecantSolve(NonlinearProblem& problem, TimedLinearStep& linear, bool uzawa_steps)
    : problem_(problem), linear_(linear),
      uzawa_(uzawa_steps ? problem.uzawa_limits() : std::nullopt),
      system_(problem.plan().make_system()) {
  FF_ASSERT(!uzawa_steps || uzawa_, "Uzawa steps need exact-constraint multipliers");
}

LaggedStep SecantSolve::solve(const VectorX* w, VectorX& next) {
  const int max_steps = uzawa_ ? uzawa_->max_steps : 1;
  LaggedStep result{std::nullopt, !uzawa_};
  UzawaSettling settling(uzawa_ ? uzawa_->tolerance : 0.0);
  for (int step = 0; step < max_steps; ++step) {
    {
      ScopedTimer timer(linear_.times(), "assembly");
      problem_.assemble_secant(w, system_); // Uzawa: same matrix each step; the load changes
    }
    if (step == 0) {
      if (const auto stop = linear_.analyse_once(system_.matrix)) return {stop, false};
      if (const auto stop = linear_.factorize(system_.matrix)) return {stop, false};
    }
    VectorX free_velocity;
    if (const auto stop = linear_.solve(system_.rhs, free_velocity)) return {stop, false};
    next = problem_.plan().expand(free_velocity, problem_.prescribed_values());
    if (!uzawa_) break;
    if (const auto stop = uzawa_update(problem_, next, settling, result.constraints_converged))
      return {stop, false};
    if (result.constraints_converged) break;
  }
  return result;
}

namespace {

/// The reduction of the nonlinear residual a loose step's linear solve achieves.
/// Started from the last iterate uⁿ, the solve's initial residual b(uⁿ) − A(uⁿ) uⁿ is
/// the nonlinear residual F(uⁿ) of the secant map's fixed point; the exact step would
/// remove all of it, a loose one leaves η ‖F(uⁿ)‖. The inexact map uⁿ⁺¹ = S(uⁿ) + eₙ
/// then contracts at about ρ + η κ instead of ρ (κ: how far a residual left behind moves
/// the iterate, relative to the step). The secant loop's tail contracts slowly, ρ ≈
/// 0.88–0.92 on the 3D round quarter and 0.97 on the 2D paper case (measured: the last
/// changes of the runs in docs/benchmarks.md), so η κ must stay well below 1 − ρ ≥ 0.03:
/// η = 1e-2 with κ of order one (Newton's Eisenstat–Walker forcing allows up to 0.9, for
/// a loop that contracts fast). Measured: the step counts did not change
/// (docs/benchmarks.md "Scale").
constexpr Real inexact_forcing = 1e-2;
/// A step whose predicted change is below this multiple of δ may stop the loop: exact.
/// A loose step that lands below δ all the same costs one more (exact) step, since it
/// cannot stop the loop; the margin keeps that rare without solving the slow tail of
/// the loop (17 steps per decade in 3D) exactly.
constexpr Real exact_margin = 2;

/// Whether a loose step's result is mixed like an exact one's (Anderson acceleration).
/// Its image errs by about η ‖f‖ (inexact_forcing), which moves the difference columns
/// by η/(1 − ρ) of their size (≈ 0.1 in the 3D tail) and the mixing weights by about as
/// much: the mix still gains far more than that, and a mix it spoils is caught by the
/// residual safeguard (solvers/anderson_acceleration.hpp). Measured (docs/benchmarks.md
/// "Anderson acceleration"): loose steps unmixed, the 3D round quarter at h = 0.25 took 25
/// fine steps against 26 plain (most of its steps are loose), mixed 19; the 2D iterative
/// path at h = 0.625 38 against 60, mixed 26. Loose steps never stop the loop, mixed or not.
constexpr bool mix_loose_steps = true;

/// The residual reduction step n + 1 needs from its linear solve (0: the back-end's own
/// tolerance), from the last two relative changes cₙ, cₙ₋₁ (0 when not yet known).
/// The steps that may end the loop keep the own tolerance (today's accuracy): the
/// final iterate then satisfies the same bound ρ/(1 − ρ) δ against the fixed point as
/// with exact steps, since that bound needs only the last step exact.
/// A step whose change cannot be predicted is loose: the first (its start is a
/// prolongation from a coarser mesh or a constant-viscosity solve, whose change is the
/// nonlinearity's or the discretisation's, far above δ) and, with Anderson mixing
/// (`steady_contraction` false: mixed changes do not shrink at a steady rate), every
/// step is predicted with the contraction 1: exact once the last change itself is below
/// the margin. Either way a misjudged loose step costs one more step, never accuracy:
/// loose steps cannot stop the loop. Measured (docs/benchmarks.md "Loose first steps, one sweep
/// each way"): from the coarse start the first two steps were exact, 35 and 30 Krylov iterations at
/// h = 0.125 and 57 and 42 at 1 M dofs, against 6–19 loose; with the latch of session 13
/// (once exact, always exact) 3–4 exact steps still changed by more than δ.
Real inexact_reduction(Real change, Real previous_change, Real tolerance, bool steady_contraction) {
  if (change <= 0) return inexact_forcing; // the first step: unpredictable, far from δ
  const Real contraction = steady_contraction && previous_change > 0
                               ? std::min<Real>(1, change / previous_change)
                               : Real(1);
  return contraction * change < exact_margin * tolerance ? 0 : inexact_forcing;
}

} // namespace

SecantOutcome secant_iteration(NonlinearProblem& problem, LaggedSolve& lagged,
                               const IterationControl& control,
                               const IterationObserver& on_iteration, const VectorX* start) {
  SecantOutcome outcome;
  outcome.velocity = problem.prescribed_values(); // u = 0 except prescribed values
  lagged.loosen(0); // the start is solved exactly (a solver may come from another loop)
  if (start) {
    outcome.velocity = *start;
  } else if (const LaggedStep first = lagged.solve(nullptr, outcome.velocity); first.stop) {
    outcome.stop_reason = *first.stop;
    return outcome;
  }
  std::optional<AndersonAcceleration> anderson;
  if (control.acceleration == NonlinearAcceleration::Anderson)
    anderson.emplace(control.acceleration_depth, problem.ghosted() ? &problem : nullptr);
  const assembly::ScatterPlan& plan = problem.plan();
  // The iterate the next step lags its coefficients at: the last step's result, or with
  // Anderson acceleration a mix of the last results. outcome.velocity is always the
  // last step's result G(iterate), the velocity the system's reaction, the pressure of a
  // saddle point and the after-iteration state were computed with.
  VectorX iterate = outcome.velocity;
  int mixed_columns = 0;
  Real change = 0, previous_change = 0; // the last two relative changes (0: none yet)
  for (int iteration = 1; iteration <= control.max_iterations; ++iteration) {
    const auto start_time = std::chrono::steady_clock::now();
    VectorX next;
    const Real reduction =
        inexact_reduction(change, previous_change, control.tolerance, !anderson.has_value());
    const bool loose = lagged.loosen(reduction);
    const LaggedStep step = lagged.solve(&iterate, next);
    if (step.stop) {
      outcome.stop_reason = *step.stop;
      return outcome;
    }
    previous_change = change;
    // The change of the map's step from the iterate it started at, mixed or not:
    // ‖G(x) − x‖/‖G(x)‖ < δ bounds G(x)'s distance to the fixed point by ρ/(1 − ρ) δ
    // for any x (ρ: G's contraction), so the stop keeps its meaning with acceleration.
    change = problem.norm(next - iterate) / problem.norm(next);
    IterationRecord record;
    record.iteration = iteration;
    record.relative_change = change;
    record.pressure = problem.driven_force(lagged.system(), next) / problem.driven_height();
    record.mixed_columns = mixed_columns;
    record.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    outcome.velocity = std::move(next);
    outcome.history.push_back(record);
    if (on_iteration) on_iteration(record);
    // A loose step is not the exact map's: it cannot end the loop (the next, exact, may).
    const auto own = stop_after_iteration(change, change, record.pressure, control.tolerance,
                                          step.constraints_converged && !loose);
    const AfterIteration after = problem.after_iteration(
        {iteration, &outcome.velocity, own == StopReason::Converged, change});
    if (const auto stop = stop_with_hook(own, after)) {
      outcome.stop_reason = *stop;
      return outcome;
    }
    if (!anderson) {
      iterate = outcome.velocity;
      continue;
    }
    // Pairs made under constraint multipliers that moved during the step (an unsettled
    // Uzawa loop), or before the after-iteration hook updated the problem (exact
    // friction's λ̂, updated when the inner loop converged but the hook did not settle),
    // belong to another map than the next step's: forget them; the next pair starts a
    // new history.
    if (!step.constraints_converged ||
        (own == StopReason::Converged && problem.changes_after_iteration())) {
      anderson->forget();
      mixed_columns = 0;
      iterate = outcome.velocity;
      continue;
    }
    const VectorX mixed = anderson->next(
        plan.free_values(iterate), plan.free_values(outcome.velocity), mix_loose_steps || !loose);
    mixed_columns = anderson->last_columns();
    iterate =
        mixed_columns > 0 ? plan.expand(mixed, problem.prescribed_values()) : outcome.velocity;
  }
  outcome.stop_reason = StopReason::MaxIterations;
  return outcome;
}

SecantOutcome secant_iteration(NonlinearProblem& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const IterationObserver& on_iteration, PhaseTimes& times,
                               const VectorX* start) {
  TimedLinearStep linear(solver, times);
  SecantSolve lagged(problem, linear);
  return secant_iteration(problem, lagged, control, on_iteration, start);
}

} // namespace formflow::solvers
