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
//  * Newton's own stop rule plus "the Coulomb conditions hold" (hook): it converges
//    when an iteration changed u by < δ with λ̂ frozen AND the pair (u, λ̂ updated)
//    has a Coulomb residual < δ at the problem's scale ‖λ‖/‖u_T‖
//    (solvers/friction_residual.hpp), not at the algorithm's r = 1e8, which made the
//    old test, the multiplier change, wait for slips of 1e-12 (issue 16), AND the
//    residual's power is < δ of the ram's (solvers/power_residual.hpp: reaction = total
//    power to δ; the velocity change cannot see O(1) traction errors at stuck points);
//    a loop whose merit max(change, residual, residual's power) sets no new minimum for
//    8 iterations stops Stalled.
//  * The tangent keeps λ̂ frozen (assembly/newton_system.cpp): the stick penalty r
//    stays in the SPD tangent and the nonlocal dτ_f in the GMRES coupling. A
//    semismooth Newton on (u, λ) would turn stick points into the constraint
//    u_T = 0 with λ as its multiplier: an indefinite saddle point CHOLMOD cannot take.
//  * At stick points the step itself is the Alart–Curnier one, λ⁺ = λ̂ + r u_T⁺ (the
//    update after the step uses the new u), at slip points λ⁺ = τ_f t̂ (plane; the
//    tangent-plane stiffness s r (P − t̂ t̂ᵀ) in 3D): in 2D this loop already is the
//    condensed semismooth Newton of issue 16's suggestion, λ eliminated point by
//    point, stick by the augmented update (u_T = 0 holds at the fixed point, to the
//    residual's δ, not after each step as a constraint would impose it).
//  * The augmentation r = 100/d_N of friction.newton_augmentation: with r = 1/d_N the
//    stick penalty leaves slips of τ_f/r ≈ 1e-6 per update and the stick zones take
//    several updates to form (μ = 0.2, h = 0: 55 iterations to δ = 1e-4 with the old
//    multiplier test, 24 with 100/d_N).
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
