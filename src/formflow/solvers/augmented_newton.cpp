// SPDX-License-Identifier: MIT
// The inexact augmented Lagrangian around Newton for exact Coulomb friction.
//
// Why updates between Newton steps and not a Newton solve to δ per update
// (augmented_lagrangian with a Newton InnerSolve): with r = 1/d_N the Uzawa
// update itself settles in a few steps (docs/friction.md: the stuck points slip
// only 1e-9–1e-12 after a few updates); the secant AL loop's 30–45 updates at
// δ = 1e-4 track its linearly converging inner solve. Each inner Newton solve
// costs at least one factorisation, so an update per Newton iteration is the
// cheapest the outer loop can be; updating before the velocity has settled
// wastes nothing since the next Newton step starts from the new λ̂ anyway.
// Why not a semismooth Newton on (u, λ): at stick points the law becomes the
// constraint u_T = 0 with λ as its multiplier, an indefinite saddle point that
// the CHOLMOD tangent cannot take; the frozen-λ̂ form keeps the stick penalty r
// in the SPD tangent and leaves the nonlocal dτ_f to the GMRES coupling.
#include "formflow/solvers/augmented_newton.hpp"

#include <cmath>

namespace formflow::solvers {

template <int dim>
AugmentedOutcome<dim> augmented_newton(const assembly::FormingProblem<dim>& problem,
                                       LinearSolver& solver, const IterationControl& control,
                                       const IterationObserver& on_iteration, PhaseTimes& times,
                                       const VectorX* initial) {
  AugmentedOutcome<dim> outcome;
  FrictionMultiplierHook<dim> hook;
  hook.multipliers = &outcome.multipliers;
  bool nonfinite = false;
  hook.after_iteration = [&](const VectorX& velocity, Real change) {
    if (change > control.newton_start) return false;  // far from the solution: λ̂ would be noise
    outcome.multiplier_change = update_friction_multipliers(problem, velocity, outcome.multipliers);
    ++outcome.augmentations;
    if (!std::isfinite(outcome.multiplier_change)) nonfinite = true;
    return outcome.multiplier_change < control.tolerance;
  };
  outcome.solve = newton_iteration(problem, solver, control, on_iteration, times, initial, &hook);
  if (nonfinite && outcome.solve.stop_reason != StopReason::Converged)
    outcome.solve.stop_reason = StopReason::NonFinite;
  return outcome;
}

template AugmentedOutcome<2> augmented_newton<2>(const assembly::FormingProblem<2>&, LinearSolver&,
                                                 const IterationControl&, const IterationObserver&,
                                                 PhaseTimes&, const VectorX*);
template AugmentedOutcome<3> augmented_newton<3>(const assembly::FormingProblem<3>&, LinearSolver&,
                                                 const IterationControl&, const IterationObserver&,
                                                 PhaseTimes&, const VectorX*);

}  // namespace formflow::solvers
