// SPDX-License-Identifier: MIT
// The inexact augmented Lagrangian around Newton for exact Coulomb friction.
//
// Design (measured on mesh II, docs/friction.md "Cost"; numbers there):
//  * One Newton loop, the multipliers λ̂ updated after every iteration, rather
//    than a Newton solve to δ per update (augmented_lagrangian with a Newton
//    InnerSolve): every inner solve costs at least one factorisation, so an
//    update per Newton iteration is the cheapest the outer loop can be, and the
//    Newton duals and the symbolic analysis carry over. Updating only once the
//    velocity change is below 1e-2 or 1e-3 gave the same or more iterations.
//  * Newton's own stop rule plus "the multipliers settled" (hook): it converges
//    when an iteration changed u by < δ with λ̂ frozen AND the update it produced
//    changed λ̂ by < δ in L²(Γ3), the rule of the secant AL loop (docs/friction.md).
//  * The tangent keeps λ̂ frozen (assembly/newton_system.cpp): the stick penalty r
//    stays in the SPD tangent and the nonlocal dτ_f in the GMRES coupling. A
//    semismooth Newton on (u, λ) would turn stick points into the constraint
//    u_T = 0 with λ as its multiplier: an indefinite saddle point CHOLMOD cannot take.
//  * The velocity converges in 6–8 iterations as for the regularised law; the rest
//    is the Uzawa tail of tractions at stuck points of the near-rigid dead-metal
//    zone, which the velocity hardly feels (neighbouring points drifting in
//    opposite directions). Its rate improves with r, hence the stiffer default
//    r = 100/d_N of friction.newton_augmentation (1/d_N: 55 iterations for μ = 0.2,
//    h = 0 at δ = 1e-4; 100/d_N: 24; 1e3 and 1e4/d_N alike).
#include "formflow/solvers/augmented_newton.hpp"

namespace formflow::solvers {

template <int dim>
AugmentedOutcome<dim> augmented_newton(const assembly::FormingProblem<dim>& problem,
                                       LinearSolver& solver, const IterationControl& control,
                                       const IterationObserver& on_iteration, PhaseTimes& times,
                                       const VectorX* initial) {
  AugmentedOutcome<dim> outcome;
  FrictionMultiplierHook<dim> hook;
  hook.multipliers = &outcome.multipliers;
  hook.after_iteration = [&](const VectorX& velocity) {
    outcome.multiplier_change = update_friction_multipliers(problem, velocity, outcome.multipliers);
    ++outcome.augmentations;
    return outcome.multiplier_change < control.tolerance;
  };
  // A non-finite multiplier change never counts as settled, and the next
  // assembly with it stops the Newton loop as NonFinite.
  outcome.solve = newton_iteration(problem, solver, control, on_iteration, times, initial, &hook);
  return outcome;
}

template AugmentedOutcome<2> augmented_newton<2>(const assembly::FormingProblem<2>&, LinearSolver&,
                                                 const IterationControl&, const IterationObserver&,
                                                 PhaseTimes&, const VectorX*);
template AugmentedOutcome<3> augmented_newton<3>(const assembly::FormingProblem<3>&, LinearSolver&,
                                                 const IterationControl&, const IterationObserver&,
                                                 PhaseTimes&, const VectorX*);

} // namespace formflow::solvers
