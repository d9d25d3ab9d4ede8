// SPDX-License-Identifier: MIT
// What the nonlinear drivers (secant, Newton, Uzawa, saddle point, augmentation)
// ask of a problem: the seam between solvers/ and the physics (issue 13).
//
// A virtual interface, not a concept: every call below costs a whole cell loop (or a
// Γ3 loop) and happens a few times per iteration, so the indirection is free, while
// the drivers compile once for every problem and dimension instead of per template
// argument, and a problem can be wrapped (the friction augmentation) or faked (tests)
// by a plain subclass. The drivers never see FormingProblem (the adapter is
// solvers/forming_nonlinear_problem.hpp).
#pragma once

#include "formflow/assembly/owned_dofs.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/core/types.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace formflow::solvers {

/// The dual variables Newton's tangent is built with (primal–dual linearisation;
/// for the forming problem the stress w and slip direction λ, solvers/newton_duals.hpp).
/// Opaque to the driver, which only keeps, copies (a trial step) and hands them back.
class DualState {
public:
  virtual ~DualState() = default;
  virtual std::unique_ptr<DualState> clone() const = 0;
};

/// What the after-iteration hook sees of the iteration just recorded.
struct IterationState {
  int iteration = 0;                 ///< 1-based, as in IterationRecord
  const VectorX* velocity = nullptr; ///< the new iterate (full dof vector)
  /// The driver's own stop rule says converged (change < δ, finite, inner
  /// constraints settled): the hook's own condition is all that is missing.
  bool converged = false;
  /// The relative change the driver's own stop rule tested against δ.
  Real relative_change = 0.0;
  /// The internal force at the new iterate (full dof vector; free rows: the residual
  /// R(u)) when the driver evaluated it there (Newton steps), else null.
  const VectorX* internal_force = nullptr;
};

/// The hook's verdict: whether its state (e.g. multipliers) has settled, or a reason to stop.
struct AfterIteration {
  bool settled = true;
  std::optional<StopReason> stop;
};

/// Exact constraints enforced by Uzawa steps inside each secant step.
struct UzawaLimits {
  Real tolerance = 0.0; ///< relative multiplier change that ends the steps
  int max_steps = 1;    ///< steps per secant step
};

/// One linear constraint c·δ = target on a Newton step, c a unit vector on a few free
/// rows (exact friction's u_T = 0 at a stuck node: c its tangent on the node's free
/// dofs, target −u_T). The constraints one problem returns are orthonormal.
struct StepConstraint {
  std::vector<Index> rows;        ///< free-system rows of c's entries
  std::vector<Real> coefficients; ///< c on those rows, ‖c‖ = 1
  Real target = 0.0;              ///< the value c·δ must take
};

/// A steady nonlinear problem R(u) = 0 over full dof vectors (free and prescribed).
/// Const methods are pure functions of their arguments and the problem's frozen
/// state; the non-const ones change that state (the stored coupling, multipliers).
class NonlinearProblem {
public:
  virtual ~NonlinearProblem() = default;

  // --- sizes and Dirichlet data --------------------------------------------------
  /// Free/prescribed numbering and the sparsity pattern of every system below.
  virtual const assembly::ScatterPlan& plan() const = 0;
  /// The prescribed values on their dofs, 0 elsewhere (full dof vector).
  virtual const VectorX& prescribed_values() const = 0;

  // --- the secant system and the monitored force ----------------------------------
  /// K(w) u = F with the secant (lagged) coefficients of w; w = nullptr: the
  /// problem's starting coefficients (constant viscosity).
  virtual void assemble_secant(const VectorX* w, assembly::LinearSystem& system) const = 0;
  /// The driven force read from a secant system solved for `u` (its reaction).
  virtual Real driven_force(const assembly::LinearSystem& system, const VectorX& u) const = 0;
  /// The same from an internal force of assemble_newton.
  virtual Real internal_driven_force(const VectorX& internal_force) const = 0;
  /// Monitored pressure = driven force / driven height.
  virtual Real driven_height() const = 0;

  // --- Newton ---------------------------------------------------------------------
  /// Empty duals: the primal choice, i.e. the exact tangent at the current iterate.
  virtual std::unique_ptr<DualState> make_duals() const = 0;
  /// One pass at `u`: the internal force f(u) on every dof (free rows: the residual
  /// R(u)); with `tangent`, also the symmetric part T of the Jacobian built with
  /// `duals` and the unsymmetric rest N, kept for apply_coupling.
  virtual void assemble_newton(const VectorX& u, const DualState& duals, VectorX& internal_force,
                               assembly::LinearSystem* tangent) = 0;
  /// N of the last assemble_newton with a tangent is not zero (on any rank).
  virtual bool has_coupling() const = 0;
  /// y += N x on free dof vectors (a distributed run: this rank's share of N x).
  virtual void apply_coupling(const VectorX& x_free, VectorX& y_free) const = 0;
  /// A distributed run (issue 20) assembles each rank's own cells: the tangent, the
  /// coupling and their products are the rank's shares. Replaces `values` (a free
  /// vector) by the sum of the ranks', ghosted like the velocity (collective; every rank
  /// holding an entry gets the same bits). One rank: nothing to do.
  virtual void add_up_shares(VectorX& values) const { static_cast<void>(values); }
  /// A distributed run's velocities, steps and solutions are ghosted (docs/petsc.md):
  /// each rank holds the entries of its own cells' dofs, NaN elsewhere. The drivers'
  /// inner products therefore go through `dot` (full-length or free vectors; each dof
  /// counted once, collective, the same bits on every rank), and a vector a driver
  /// must read whole goes through `replicate` (collective). One rank: the plain ones.
  virtual Real dot(const VectorX& a, const VectorX& b) const { return a.dot(b); }
  Real norm(const VectorX& a) const { return std::sqrt(dot(a, a)); }
  virtual void replicate(VectorX& values) const { static_cast<void>(values); }
  /// Whether the vectors are ghosted (a distributed run); false: dot and replicate are
  /// the plain ones, and a driver may use whole-vector algebra (Eigen's QR) as it is.
  virtual bool ghosted() const { return false; }
  /// The R factor (c × c, upper triangular) of a tall matrix of c full-length or free
  /// columns held ghosted: QR of each rank's owned rows, then of their stacked R's (TSQR).
  /// Collective; the same bits on every rank. One rank: QR of `tall`.
  virtual MatrixX r_factor(const MatrixX& tall) const {
    return assembly::OwnedDofs().r_factor(tall);
  }
  /// The duals after the Newton step `step` from `u` to `next` (the dual Newton update).
  virtual void update_duals(const VectorX& u, const VectorX& step, const VectorX& next,
                            DualState& duals) const = 0;
  /// The duals after a secant step from `previous` (null: the start) to `next`.
  virtual void secant_duals(const VectorX* previous, const VectorX& next,
                            DualState& duals) const = 0;

  // --- exact constraints by Uzawa steps (optional) --------------------------------
  /// Limits of the Uzawa steps; nothing when the problem has no such constraints.
  virtual std::optional<UzawaLimits> uzawa_limits() const { return std::nullopt; }
  /// One Uzawa update from the velocity just solved for; the relative multiplier change.
  virtual Real update_constraint_multipliers(const VectorX& /*velocity*/) { return 0.0; }

  // --- constraints inside the Newton step (optional) -------------------------------
  /// Linear constraints the next Newton step from `u` must meet exactly (the step is
  /// condensed onto them, solvers/exact_stick.hpp); empty: none. Called after the
  /// tangent at `u` was assembled.
  virtual std::vector<StepConstraint> step_constraints(const VectorX& /*u*/) const { return {}; }
  /// After a constrained step of length t: `reactions[k]` = c_k·(R(u) + J δ), the force
  /// the k-th constraint had to supply for the full step (its multiplier's change, up to
  /// the constraint's weight), so the problem can take t of it.
  virtual void constrained_step_taken(const std::vector<Real>& /*reactions*/, Real /*t*/) {}
  /// The smallest t in (0, 1] at which a slipping point's slip would reverse along
  /// u + t·step (exact stick: a kink of the residual along the step); +∞ if none.
  virtual Real slip_reversal(const VectorX& /*u*/, const VectorX& /*step*/) const {
    return std::numeric_limits<Real>::infinity();
  }

  // --- the after-iteration hook ---------------------------------------------------
  /// after_iteration may change the problem (Newton then cannot reuse a tangent
  /// assembled ahead with the old state).
  virtual bool changes_after_iteration() const { return false; }
  /// Called once after every recorded iteration, before the stop rule; a driver
  /// converges only when its own rule and the hook's `settled` agree.
  virtual AfterIteration after_iteration(const IterationState& /*state*/) { return {}; }
};

} // namespace formflow::solvers
