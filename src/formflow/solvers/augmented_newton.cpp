// SPDX-License-Identifier: MIT
// The inexact augmented Lagrangian around Newton for exact Coulomb friction.
//
// Design (measured on mesh II, docs/friction.md "Cost"; numbers there):
//  * One Newton loop, the multipliers λ̂ updated after every iteration, rather
//    than a Newton solve to δ per update (the ConvergedIterate schedule around
//    Newton): every inner solve costs at least one factorisation, so an
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
AugmentedOutcome<dim> augmented_newton(FormingNonlinearProblem<dim>& problem, LinearSolver& solver,
                                       const IterationControl& control,
                                       const IterationObserver& on_iteration, PhaseTimes& times,
                                       const VectorX* initial) {
  return augment_friction(
      problem, AugmentationSchedule::EveryIteration, control, [&](NonlinearProblem& inner) {
        return newton_iteration(inner, solver, control, on_iteration, times, initial);
      });
}

template AugmentedOutcome<2> augmented_newton<2>(FormingNonlinearProblem<2>&, LinearSolver&,
                                                 const IterationControl&, const IterationObserver&,
                                                 PhaseTimes&, const VectorX*);
template AugmentedOutcome<3> augmented_newton<3>(FormingNonlinearProblem<3>&, LinearSolver&,
                                                 const IterationControl&, const IterationObserver&,
                                                 PhaseTimes&, const VectorX*);

} // namespace formflow::solvers
