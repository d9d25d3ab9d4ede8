// SPDX-License-Identifier: MIT
// Kachanov's secant-modulus iteration (SPEC §3, eq. 5.2/5.3) over any nonlinear
// problem, with the linear solve of each step as a part that can be swapped (plain,
// with Uzawa steps, the saddle point).
#pragma once

#include "formflow/core/timer.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"
#include "formflow/solvers/stop_reason.hpp"
#include "formflow/solvers/timed_linear_step.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace formflow::solvers {

struct SecantOutcome {
  VectorX velocity; ///< the last iterate (full dof vector)
  StopReason stop_reason = StopReason::MaxIterations;
  std::vector<IterationRecord> history;
};

/// Callback receiving each iteration record (the monitor).
using IterationObserver = std::function<void(const IterationRecord&)>;

/// What one lagged solve reports: a reason to stop at once, and whether an
/// inner constraint loop (Uzawa multipliers) settled; a plain solve has none.
struct LaggedStep {
  std::optional<StopReason> stop;
  bool constraints_converged = true;
};

/// How one secant step solves the linear problem with the lagged coefficients.
class LaggedSolve {
public:
  virtual ~LaggedSolve() = default;
  /// Solves with the secant coefficients of `w` (nullptr: the constant starting
  /// ones) for the full velocity `next`.
  virtual LaggedStep solve(const VectorX* w, VectorX& next) = 0;
  /// The system of the last solve, whose reaction (loads included) is the driven force.
  virtual const assembly::LinearSystem& system() const = 0;
  /// An inexact next step: its linear solves may stop once they have reduced the
  /// residual of their start by `reduction` (0: as accurate as the back-end's own
  /// tolerance). Returns whether the step is then less accurate than the own tolerance
  /// (only an iterative back-end can be; the loop does not stop on such a step).
  virtual bool loosen(Real reduction) {
    static_cast<void>(reduction);
    return false;
  }
};

/// K(w) u = F: assemble, factorise once, solve. With `uzawa_steps` (the problem has
/// exact constraints, NonlinearProblem::uzawa_limits) the solve is repeated with the
/// same factorisation after each multiplier update until the multipliers change by
/// less than the limits' tolerance (or max_steps): the augmentation r Bᵀ M⁻¹ B, r N Nᵀ
/// is in the matrix, only the load −Bᵀλ changes between the steps (issue 5).
class SecantSolve final : public LaggedSolve {
public:
  SecantSolve(NonlinearProblem& problem, TimedLinearStep& linear, bool uzawa_steps = false);
  LaggedStep solve(const VectorX* w, VectorX& next) override;
  const assembly::LinearSystem& system() const override { return system_; }

private:
  NonlinearProblem& problem_;
  TimedLinearStep& linear_;
  std::optional<UzawaLimits> uzawa_;
  assembly::LinearSystem system_;
};

/// From the constant-viscosity solution u⁰ (or `start`, a warm start), solves
/// uⁿ⁺¹ = solve(uⁿ) until ‖uⁿ⁺¹ − uⁿ‖/‖uⁿ⁺¹‖ < δ, the lagged solve's constraints
/// settled and the problem's after-iteration hook settled. Each iteration is
/// recorded with the pressure read from the lagged solve's system.
/// Inexact steps (a lagged solve whose back-end is iterative, LaggedSolve::loosen):
/// while the change is far from δ, a step's linear solve only reduces the residual of
/// its start (the last iterate: the nonlinear residual there) by inexact_forcing, an
/// Eisenstat–Walker-type forcing; the first step and those that may stop the loop
/// (predicted change ρ cₙ below 2 δ, ρ = cₙ/cₙ₋₁ the last contraction) are solved to
/// the back-end's own tolerance, and a loose step never stops the loop.
/// Anderson acceleration (control.acceleration): the next step lags its coefficients at
/// a mix of the last steps' results on the free dofs (solvers/anderson_acceleration.hpp)
/// instead of the last result. The change tested against δ is always that of one exact
/// step of the map from the iterate it started at, and the returned velocity is that
/// step's result (with the pressure and multipliers it was solved with). Loose steps are
/// mixed too (mix_loose_steps); once a step was predicted near δ every later one is
/// exact; a step whose constraint multipliers did not settle, or after which the
/// problem's hook changed the problem, voids the history.
SecantOutcome secant_iteration(NonlinearProblem& problem, LaggedSolve& lagged,
                               const IterationControl& control,
                               const IterationObserver& on_iteration,
                               const VectorX* start = nullptr);

/// The plain secant iteration (SecantSolve without Uzawa steps). The pattern is
/// analysed once; each iteration refactorises. Phases "assembly", "analysis",
/// "factorization", "solve" are timed.
SecantOutcome secant_iteration(NonlinearProblem& problem, LinearSolver& solver,
                               const IterationControl& control,
                               const IterationObserver& on_iteration, PhaseTimes& times,
                               const VectorX* start = nullptr);

} // namespace formflow::solvers
