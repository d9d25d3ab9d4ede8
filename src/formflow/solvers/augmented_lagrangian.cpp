// SPDX-License-Identifier: MIT
// The outer multiplier loop of exact Coulomb friction.
//
// Why an augmented Lagrangian around the secant solve, and not a semismooth Newton:
// the friction law λ = proj_{|λ| ≤ τ_f}(λ + r u_T) is the only nonsmooth part, and
// τ_f depends nonlocally on u through σ̄_N, so a semismooth Newton tangent would be
// unsymmetric and dense along Γ3. Frozen λᵏ turn friction into a load plus a stick
// penalty s·r ≤ r (s = τ_f/|λᵏ + r w_T| when slipping, 1 when sticking): the inner
// systems stay symmetric positive definite, so the existing Cholesky secant (or
// Newton) driver solves them unchanged. The Uzawa update is a proximal-point step on the dual and
// converges for every r > 0; with r = 1/d_N (the default) the stick penalty is as
// stiff as the normal contact penalty, so after the first outer step the friction is
// already that of the regularised law with d_T ≈ τ_f d_N, and the later steps only
// remove the remaining stick-zone slip. τ_f is lagged: it is evaluated at the
// current iterate in each assembly and at uᵏ in the update.
#include "formflow/solvers/augmented_lagrangian.hpp"
#include "formflow/solvers/friction_residual.hpp"
#include "formflow/solvers/power_residual.hpp"
#include "formflow/solvers/stall_watch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace formflow::solvers {

namespace {

/// Iterations without a new minimum of max(velocity change, friction residual, residual's
/// power) that
/// make exact friction's Newton loop a stall. While Newton converges its merit falls in
/// nearly every iteration; 8 leaves room for a few active-set changes. Not tuned: with
/// the residual's power in the merit (session 7) 119 of the grid's 120 Q2/Q1 cases at
/// δ = 1e-4 converged in at most 18 iterations, Q2 at 1e-8 in up to 44; the one stall
/// never got its residual's power below 1e-4 (docs/friction.md "Session 7").
constexpr int stall_window = 8;

/// Exact stick: a held node over the Coulomb limit is released when the held residual
/// (its excess) is at least 1/release_margin times the iterate's relative change, as well
/// as when the velocity has settled to δ. Not derived: an order of magnitude between the
/// excess and the iterate's own motion, read off the grid's traces (docs/friction.md
/// "Session 11"): transient excesses came with changes of their own size (0.26 at 0.10,
/// 0.044 at 0.043), persisting ones were 10 to 1000 times the change. Without it (release
/// at δ only) the slip front of plane Q1 sliding h = 0.25 μ = 0.5 moved one node per
/// Newton solve to δ = 1e-8 and stalled after 30 iterations.
constexpr Real release_margin = 0.1;

/// ‖a − b‖ and ‖a‖ in L²(Γ3), with the quadrature weights of the contact points.
template <int dim>
std::pair<Real, Real> multiplier_norms(const std::vector<assembly::ContactPoint<dim>>& state,
                                       const std::vector<Point<dim>>& previous) {
  Real difference = 0.0, norm = 0.0;
  for (std::size_t k = 0; k < state.size(); ++k) {
    const Point<dim>& next = state[k].friction_traction;
    const Point<dim> old = previous.empty() ? Point<dim>::Zero() : previous[k];
    difference += (next - old).squaredNorm() * state[k].weight;
    norm += next.squaredNorm() * state[k].weight;
  }
  return {std::sqrt(difference), std::sqrt(norm)};
}

} // namespace

template <int dim>
MultiplierUpdate
update_friction_multipliers(const assembly::FormingProblem<dim>& problem, const VectorX& velocity,
                            assembly::FrictionMultipliers<dim>& multipliers,
                            const std::vector<std::size_t>& held, Real release_from) {
  // λᵏ⁺¹ = proj(λᵏ + r uᵏ_T): the traction contact_state evaluates for λᵏ at uᵏ, the
  // one the equilibrium at uᵏ was assembled with; the Coulomb residual is that pair's.
  const auto state = problem.contact_state(velocity, &multipliers);
  const auto [difference, norm] = multiplier_norms(state, multipliers.traction);
  MultiplierUpdate update;
  // No friction anywhere (μ = 0, or Γ3 entirely in tension): nothing left to update.
  update.change = norm > 0 ? difference / norm : 0.0;
  update.residual = friction_residual(state);
  std::vector<Point<dim>> asked;
  Real held_residual = 0.0;
  if (!held.empty() && multipliers.traction.size() == state.size()) {
    asked = multipliers.traction;
    held_residual = held_friction_residual(state, asked, held);
    update.residual = std::max(update.residual, held_residual);
  }
  multipliers.traction.resize(state.size());
  for (std::size_t k = 0; k < state.size(); ++k)
    multipliers.traction[k] = state[k].friction_traction;
  if (!asked.empty() && held_residual >= release_from) {
    for (std::size_t k : held) {
      const assembly::ContactPoint<dim>& point = state[k];
      const Point<dim> tangential = point.tangential_part(asked[k]);
      if (point.friction_threshold > 0 && tangential.norm() > point.friction_threshold) {
        multipliers.traction[k] = tangential;
        update.released.push_back(k);
      }
    }
  }
  return update;
}

template <int dim>
AugmentedOutcome<dim> augment_friction(FormingNonlinearProblem<dim>& problem,
                                       AugmentationSchedule schedule,
                                       const IterationControl& control, const InnerDriver& driver) {
  AugmentedOutcome<dim> outcome;
  const bool every_iteration = schedule == AugmentationSchedule::EveryIteration;
  int updates = 0;
  int inner_solves = 1; // ConvergedIterate: the first inner solve starts with the driver
  StallWatch stall(stall_window);
  std::set<std::size_t> ever_released; // exact stick: points released by the update
  // λ̂ of the last iteration (outcome.multipliers are updated after it): see AugmentedOutcome.
  assembly::FrictionMultipliers<dim> equilibrium;
  bool last_updated = false;
  problem.set_friction_multipliers(&outcome.multipliers);
  problem.set_after_iteration(
      [&](const IterationState& state) -> AfterIteration {
        // ConvergedIterate: the inner solve with λᵏ frozen goes on until it converges.
        last_updated = every_iteration || state.converged;
        if (!last_updated) return {false, std::nullopt};
        // The multipliers this iteration was assembled with, kept for the evaluation.
        equilibrium = outcome.multipliers;
        // Exact stick: a held node whose reaction leaves the Coulomb disk counts in the
        // residual (the projection would hide it), and it is released to slip once the
        // iterate has settled enough for the excess to be a verdict on the stick set: the
        // velocity settled to δ (a working-set rule: a constraint is dropped at the
        // stationary point of its working set), or the excess at least 1/release_margin
        // times the iterate's relative change. Not on any excess: the first fine iterate
        // after the coarse start asks 2.3 τ_f of a node that sticks at the solution
        // (change 0.10); released there, axisymmetric Q2 sliding h = 0.5 μ = 0.3 stalls
        // (docs/friction.md "Session 11").
        const std::vector<std::size_t> held = problem.take_held_points();
        const MultiplierUpdate update = update_friction_multipliers(
            problem.forming(), *state.velocity, outcome.multipliers, held,
            state.converged ? control.tolerance : state.relative_change / release_margin);
        // A release starts a new stick set, from whose settling the stall watch counts
        // afresh; once per point, so that nodes released, held again and released again
        // in a cycle still end as Stalled.
        bool released_new = false;
        for (std::size_t k : update.released)
          if (ever_released.insert(k).second) released_new = true;
        if (released_new) stall.restart();
        outcome.multiplier_change = update.change;
        outcome.friction_residual = update.residual;
        ++updates;
        if (!std::isfinite(update.change) || !std::isfinite(update.residual))
          return {false, StopReason::NonFinite};
        // Newton (every iteration): the Coulomb conditions' residual at the problem's
        // scale (solvers/friction_residual.hpp), and a stall watch on it and the
        // velocity change. The secant AL loop keeps its multiplier-change test.
        // Newton also asks the residual's power to be < δ of the ram's: the reaction
        // then equals the total power to δ (solvers/power_residual.hpp). At stuck points
        // an O(1) traction error is a velocity change of 1e-8 only, which the change
        // test cannot see. Not measured after a secant step: not settled then.
        const Real unbalanced =
            state.internal_force
                ? power_residual(problem.plan(), problem.forming().constraints().driven_dofs,
                                 *state.velocity, *state.internal_force,
                                 problem.ghosted() ? &problem : nullptr)
                : std::numeric_limits<Real>::infinity();
        if (std::isfinite(unbalanced)) outcome.power_residual = unbalanced;
        const bool settled = every_iteration
                                 ? std::max(update.residual, unbalanced) < control.tolerance
                                 : update.change < control.tolerance;
        if (every_iteration && !(settled && state.converged) &&
            stall.stalled(std::max({state.relative_change, update.residual, unbalanced})))
          return {false, StopReason::Stalled};
        // An unsettled update starts the next inner solve, if an iteration is left for it.
        if (!settled && state.iteration < control.max_iterations) ++inner_solves;
        return {settled, std::nullopt};
      },
      true);
  outcome.solve = driver(problem);
  // The hook and the frozen multipliers refer to this call's locals.
  problem.set_after_iteration({}, false);
  problem.set_friction_multipliers(nullptr);
  outcome.augmentations = every_iteration ? updates : inner_solves;
  // When the last iteration made no update (the secant loop stopped inside an inner
  // solve, or no iteration ran) it was assembled with the current multipliers.
  if (last_updated) outcome.multipliers = std::move(equilibrium);
  return outcome;
}

template <int dim>
AugmentedOutcome<dim> augmented_lagrangian(FormingNonlinearProblem<dim>& problem,
                                           LinearSolver& solver, const IterationControl& control,
                                           const IterationObserver& on_iteration,
                                           PhaseTimes& times) {
  return augment_friction(problem, AugmentationSchedule::ConvergedIterate, control,
                          [&](NonlinearProblem& inner) {
                            return secant_iteration(inner, solver, control, on_iteration, times);
                          });
}

template struct AugmentedOutcome<2>;
template struct AugmentedOutcome<3>;
template AugmentedOutcome<2> augment_friction<2>(FormingNonlinearProblem<2>&, AugmentationSchedule,
                                                 const IterationControl&, const InnerDriver&);
template AugmentedOutcome<3> augment_friction<3>(FormingNonlinearProblem<3>&, AugmentationSchedule,
                                                 const IterationControl&, const InnerDriver&);
template AugmentedOutcome<2> augmented_lagrangian<2>(FormingNonlinearProblem<2>&, LinearSolver&,
                                                     const IterationControl&,
                                                     const IterationObserver&, PhaseTimes&);
template AugmentedOutcome<3> augmented_lagrangian<3>(FormingNonlinearProblem<3>&, LinearSolver&,
                                                     const IterationControl&,
                                                     const IterationObserver&, PhaseTimes&);
template MultiplierUpdate update_friction_multipliers<2>(const assembly::FormingProblem<2>&,
                                                         const VectorX&,
                                                         assembly::FrictionMultipliers<2>&,
                                                         const std::vector<std::size_t>&, Real);
template MultiplierUpdate update_friction_multipliers<3>(const assembly::FormingProblem<3>&,
                                                         const VectorX&,
                                                         assembly::FrictionMultipliers<3>&,
                                                         const std::vector<std::size_t>&, Real);

} // namespace formflow::solvers
