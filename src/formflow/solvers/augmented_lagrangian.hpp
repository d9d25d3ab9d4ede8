// SPDX-License-Identifier: MIT
// Exact Coulomb friction by an augmented Lagrangian (Uzawa) wrapper around an inner
// nonlinear driver in which the friction multipliers are frozen.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <functional>
#include <limits>
#include <vector>

namespace formflow::solvers {

/// When the wrapper updates the multipliers. Both stop when an iteration changed u by
/// < δ with λ̂ frozen AND the update it produced met δ: EveryIteration (Newton) asks
/// the Coulomb residual of solvers/friction_residual.hpp to be < δ and stops as
/// Stalled when neither it nor the velocity change reached a new minimum for a
/// window of iterations; ConvergedIterate (secant) asks the relative multiplier change
/// ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖ in L²(Γ3) to be < δ, the Uzawa rule.
enum class AugmentationSchedule {
  /// After every iteration of the inner driver (Newton: an inexact augmented
  /// Lagrangian; one driver run, duals and analysis carried on).
  EveryIteration,
  /// Only after an iteration that converged with λ̂ frozen: an inner solve to δ per
  /// update, continued from its last iterate (the secant AL loop).
  ConvergedIterate,
};

/// An inner driver run over the problem the wrapper prepared (its multipliers
/// frozen in every assembly, its after-iteration hook installed).
using InnerDriver = std::function<SecantOutcome(NonlinearProblem& problem)>;

template <int dim> struct AugmentedOutcome {
  /// Final velocity, stop reason and the inner iterations of all outer steps, numbered on.
  SecantOutcome solve;
  /// The frozen λ̂ the last iterate was assembled with: its equilibrium holds with the
  /// traction proj(λ̂ + r u_T) (= the last update), so post-processing evaluates with
  /// these. Evaluating with the updated multipliers instead projected once more,
  /// proj(λᵏ⁺¹ + r u_T), which differs by r u_T at stuck points (r = 1e8: slips of 1e-9
  /// are tractions of 0.1) and broke reaction = total power where stuck points load the
  /// ram's prescribed dofs (docs/friction.md "Reaction and total power").
  assembly::FrictionMultipliers<dim> multipliers;
  int augmentations = 0;        ///< outer (multiplier) updates
  Real multiplier_change = 0.0; ///< last ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖ in L²(Γ3)
  Real friction_residual = 0.0; ///< last Coulomb residual (solvers/friction_residual.hpp)
  /// Newton: the last measured power of the residual relative to the ram's, |u_f·R_f| /
  /// |u·f on the driven dofs| (solvers/power_residual.hpp); 0 for the secant loop.
  Real power_residual = 0.0;
};

/// What one multiplier update measured.
struct MultiplierUpdate {
  Real change = 0.0; ///< ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖ in L²(Γ3) (0 without friction)
  /// friction_residual of (uᵏ, λᵏ⁺¹), and not less than held_friction_residual of the
  /// multipliers the held nodes' reactions asked for (their excess over τ_f).
  Real residual = 0.0;
  /// Held points left unprojected (release_from), so that they slip.
  std::vector<std::size_t> released;
};

/// Uzawa iteration of the augmented Lagrangian for λ_T (Alart–Curnier form), one
/// wrapper around any inner driver (secant or Newton):
///   iterate with λᵏ frozen → uᵏ;  λᵏ⁺¹ = proj_{|λ| ≤ τ_f(uᵏ)}(λᵏ + r uᵏ_T)
/// from λ⁰ = 0, on `schedule`. The driver runs once over `problem`; its iteration
/// history is the run's, `control.max_iterations` bounds all its iterations, and a
/// non-finite multiplier change stops it (NonFinite). `augmentations` counts the
/// outer steps: the updates (EveryIteration) or the inner solves begun
/// (ConvergedIterate, the last one included when it did not converge).
template <int dim>
AugmentedOutcome<dim> augment_friction(FormingNonlinearProblem<dim>& problem,
                                       AugmentationSchedule schedule,
                                       const IterationControl& control, const InnerDriver& driver);

/// Exact friction by the paper's secant method: augment_friction around the plain
/// secant iteration, an update per converged inner solve.
template <int dim>
AugmentedOutcome<dim> augmented_lagrangian(FormingNonlinearProblem<dim>& problem,
                                           LinearSolver& solver, const IterationControl& control,
                                           const IterationObserver& on_iteration,
                                           PhaseTimes& times);

/// One Uzawa update λᵏ⁺¹ = proj_{|λ| ≤ τ_f(u)}(λᵏ + r u_T) at `velocity`, in place;
/// returns ‖λᵏ⁺¹ − λᵏ‖/‖λᵏ⁺¹‖ in L²(Γ3) (0 where there is no friction at all) and the
/// Coulomb residual of (u, λᵏ⁺¹), or, if larger, that of the multipliers the exact-stick
/// step set at its `held` points from their reactions (held_friction_residual: a held
/// node whose reaction leaves the Coulomb disk). When that held residual is at least
/// `release_from` (∞: never), such points keep the multiplier their reaction asked
/// (unprojected), so that the next active-set test |λ̂ + r u_T| ≤ τ_f lets them slip
/// (docs/friction.md "Session 11").
template <int dim>
MultiplierUpdate
update_friction_multipliers(const assembly::FormingProblem<dim>& problem, const VectorX& velocity,
                            assembly::FrictionMultipliers<dim>& multipliers,
                            const std::vector<std::size_t>& held = {},
                            Real release_from = std::numeric_limits<Real>::infinity());

} // namespace formflow::solvers
