// SPDX-License-Identifier: MIT
// The outer multiplier loop of exact Coulomb friction.
//
// Why an augmented Lagrangian around the secant solve, and not a semismooth Newton:
// the friction law λ = proj_{|λ| ≤ τ_f}(λ + r u_T) is the only nonsmooth part, and
// τ_f depends nonlocally on u through σ̄_N, so a semismooth Newton tangent would be
// unsymmetric and dense along Γ3. Frozen λᵏ turn friction into a load plus a stick
// penalty s·r ≤ r (s = τ_f/|λᵏ + r w_T| when slipping, 1 when sticking): the inner
// systems stay symmetric positive definite, so the existing Cholesky secant loop
// solves them unchanged. The Uzawa update is a proximal-point step on the dual and
// converges for every r > 0; with r = 1/d_N (the default) the stick penalty is as
// stiff as the normal contact penalty, so after the first outer step the friction is
// already that of the regularised law with d_T ≈ τ_f d_N, and the later steps only
// remove the remaining stick-zone slip. τ_f is lagged: it is evaluated at the
// current iterate in each assembly and at uᵏ in the update.
#include "formflow/solvers/augmented_lagrangian.hpp"

#include <cmath>

namespace formflow::solvers {

namespace {

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
Real update_friction_multipliers(const assembly::FormingProblem<dim>& problem,
                                 const VectorX& velocity,
                                 assembly::FrictionMultipliers<dim>& multipliers) {
  // λᵏ⁺¹ = proj(λᵏ + r uᵏ_T): the traction contact_state evaluates for λᵏ at uᵏ.
  const auto state = problem.contact_state(velocity, &multipliers);
  const auto [difference, norm] = multiplier_norms(state, multipliers.traction);
  multipliers.traction.resize(state.size());
  for (std::size_t k = 0; k < state.size(); ++k)
    multipliers.traction[k] = state[k].friction_traction;
  // No friction anywhere (μ = 0, or Γ3 entirely in tension): nothing left to update.
  return norm > 0 ? difference / norm : 0.0;
}

template <int dim>
AugmentedOutcome<dim>
augmented_lagrangian(const assembly::FormingProblem<dim>& problem, const InnerSolve<dim>& inner,
                     const IterationControl& control, const IterationObserver& on_iteration) {
  AugmentedOutcome<dim> outcome;
  SecantOutcome& solve = outcome.solve;
  int used = 0;
  bool warm = false;
  while (true) {
    IterationControl inner_control = control;
    inner_control.max_iterations = control.max_iterations - used;
    if (inner_control.max_iterations <= 0) {
      solve.stop_reason = StopReason::MaxIterations;
      return outcome;
    }
    // One history and one monitor for the whole run: number the inner iterations on.
    const int offset = used;
    const IterationObserver renumbered = [&](const IterationRecord& record) {
      IterationRecord shifted = record;
      shifted.iteration += offset;
      if (on_iteration) on_iteration(shifted);
    };
    SecantOutcome step =
        inner(outcome.multipliers, warm ? &solve.velocity : nullptr, inner_control, renumbered);
    for (IterationRecord& record : step.history) {
      record.iteration += offset;
      solve.history.push_back(record);
    }
    used += static_cast<int>(step.history.size());
    solve.velocity = std::move(step.velocity);
    solve.stop_reason = step.stop_reason;
    warm = true;
    ++outcome.augmentations;
    if (step.stop_reason != StopReason::Converged) return outcome;

    outcome.multiplier_change =
        update_friction_multipliers(problem, solve.velocity, outcome.multipliers);
    if (!std::isfinite(outcome.multiplier_change)) {
      solve.stop_reason = StopReason::NonFinite;
      return outcome;
    }
    if (outcome.multiplier_change < control.tolerance) return outcome; // Converged
  }
}

template <int dim>
InnerSolve<dim> secant_inner_solve(const assembly::FormingProblem<dim>& problem,
                                   LinearSolver& solver, PhaseTimes& times) {
  return [&problem, &solver, &times](const assembly::FrictionMultipliers<dim>& multipliers,
                                     const VectorX* start, const IterationControl& control,
                                     const IterationObserver& on_iteration) {
    return secant_iteration(problem, solver, control, on_iteration, times, &multipliers, start);
  };
}

template struct AugmentedOutcome<2>;
template struct AugmentedOutcome<3>;
template AugmentedOutcome<2> augmented_lagrangian<2>(const assembly::FormingProblem<2>&,
                                                     const InnerSolve<2>&, const IterationControl&,
                                                     const IterationObserver&);
template AugmentedOutcome<3> augmented_lagrangian<3>(const assembly::FormingProblem<3>&,
                                                     const InnerSolve<3>&, const IterationControl&,
                                                     const IterationObserver&);
template Real update_friction_multipliers<2>(const assembly::FormingProblem<2>&, const VectorX&,
                                             assembly::FrictionMultipliers<2>&);
template Real update_friction_multipliers<3>(const assembly::FormingProblem<3>&, const VectorX&,
                                             assembly::FrictionMultipliers<3>&);
template InnerSolve<2> secant_inner_solve<2>(const assembly::FormingProblem<2>&, LinearSolver&,
                                             PhaseTimes&);
template InnerSolve<3> secant_inner_solve<3>(const assembly::FormingProblem<3>&, LinearSolver&,
                                             PhaseTimes&);

} // namespace formflow::solvers
