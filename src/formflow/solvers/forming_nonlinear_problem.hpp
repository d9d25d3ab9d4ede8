// SPDX-License-Identifier: MIT
// The forming problem (assembly::FormingProblem) seen through the drivers'
// interface (solvers/nonlinear_problem.hpp).
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace formflow::solvers {

/// Adapter of a FormingProblem (not owned; must outlive this) to NonlinearProblem.
/// It adds the state the drivers change between assemblies: exact friction's frozen
/// multipliers λ̂ (passed to every assembly), the last unsymmetric coupling N, and
/// an after-iteration hook (the friction augmentation installs one).
template <int dim> class FormingNonlinearProblem final : public NonlinearProblem {
public:
  using Hook = std::function<AfterIteration(const IterationState&)>;

  explicit FormingNonlinearProblem(const assembly::FormingProblem<dim>& problem)
      : problem_(problem) {}

  const assembly::FormingProblem<dim>& forming() const { return problem_; }

  /// Exact friction: the multipliers λ̂ frozen in every assembly (not owned; null: λ̂ = 0).
  /// With exact stick (below) the Newton steps change the stuck nodes' λ̂
  /// (constrained_step_taken).
  void set_friction_multipliers(assembly::FrictionMultipliers<dim>* multipliers) {
    friction_ = multipliers;
  }
  /// friction.stick = "exact" (exact friction, nodal contact points): every Newton step
  /// imposes u_T = 0 at the Γ3 nodes that stick for the current λ̂ (step_constraints).
  void enable_exact_stick();
  /// Called by after_iteration; `changes`: the hook changes the problem (λ̂).
  void set_after_iteration(Hook hook, bool changes) {
    hook_ = std::move(hook);
    hook_changes_ = changes;
  }

  const assembly::ScatterPlan& plan() const override { return problem_.plan(); }
  const VectorX& prescribed_values() const override { return problem_.constraints().values; }

  void assemble_secant(const VectorX* w, assembly::LinearSystem& system) const override {
    problem_.assemble(w, system, friction_);
  }
  Real driven_force(const assembly::LinearSystem& system, const VectorX& u) const override {
    return problem_.driven_force(system, u);
  }
  Real internal_driven_force(const VectorX& internal_force) const override {
    return problem_.driven_force(internal_force);
  }
  Real driven_height() const override { return problem_.driven_height(); }

  std::unique_ptr<DualState> make_duals() const override;
  /// τ_f is evaluated at `u` (the exact residual the Jacobian differentiates).
  void assemble_newton(const VectorX& u, const DualState& duals, VectorX& internal_force,
                       assembly::LinearSystem* tangent) override;
  bool has_coupling() const override { return coupled_; }
  void apply_coupling(const VectorX& x_free, VectorX& y_free) const override {
    problem_.apply_coupling(coupling_, x_free, y_free);
  }
  void add_up_shares(VectorX& values) const override;
  Real dot(const VectorX& a, const VectorX& b) const override {
    return problem_.discretisation().owned_dofs().dot(a, b);
  }
  void replicate(VectorX& values) const override {
    problem_.discretisation().owned_dofs().replicate(values);
  }
  bool ghosted() const override { return problem_.discretisation().owned_dofs().distributed(); }
  MatrixX r_factor(const MatrixX& tall) const override {
    return problem_.discretisation().owned_dofs().r_factor(tall);
  }
  void update_duals(const VectorX& u, const VectorX& step, const VectorX& next,
                    DualState& duals) const override;
  void secant_duals(const VectorX* previous, const VectorX& next, DualState& duals) const override;

  /// Uzawa steps when the attached ConstraintMultipliers need them (d = 0 with a
  /// condensed pressure, or d_N = 0).
  std::optional<UzawaLimits> uzawa_limits() const override;
  /// λ ← λ + r M⁻¹B u, λ_N ← λ_N + r_N u_N on the attached ConstraintMultipliers.
  Real update_constraint_multipliers(const VectorX& velocity) override;

  /// Exact stick: u_T = 0 at every eligible Γ3 node whose points all stick for the
  /// current λ̂ (|λ̂ + r u_T| ≤ τ_f), one constraint per tangent direction. The assembly
  /// is the augmented one (traction λ̂ + r u_T, stiffness r): once u_T = 0 holds the
  /// traction is λ̂, and the penalty's force and stiffness cancel in the reaction.
  std::vector<StepConstraint> step_constraints(const VectorX& u) const override;
  /// λ̂ at the constrained nodes += t × (−reaction / the node's weight) along the tangent.
  void constrained_step_taken(const std::vector<Real>& reactions, Real t) override;
  /// The contact points of the nodes the last Newton step held (whose λ̂ that step set
  /// from their reactions, not yet projected onto the Coulomb disk), handed over once:
  /// empty after a step that held none, or when no Newton step ran since the last call.
  std::vector<std::size_t> take_held_points() { return std::exchange(held_points_, {}); }
  /// Over the eligible nodes that slip for the current λ̂: where u_T·t̂ (t̂ the
  /// traction's direction) reaches 0 along the step.
  Real slip_reversal(const VectorX& u, const VectorX& step) const override;

  bool changes_after_iteration() const override { return hook_ && hook_changes_; }
  AfterIteration after_iteration(const IterationState& state) override {
    return hook_ ? hook_(state) : AfterIteration{};
  }

private:
  const assembly::FormingProblem<dim>& problem_;
  /// A Γ3 node whose stick is imposed exactly: its points (all with one normal) and
  /// rows (−1 for a prescribed dof).
  struct StickNode {
    Index node = 0;
    std::vector<std::size_t> points;
    std::array<Index, dim> rows{};
    Real weight = 0.0; ///< Σ JxW of its points: λ̂ loads the node by weight × λ̂
  };
  /// The nodes eligible for exact stick: nodal contact points, a free dof at the node,
  /// one normal at all its points (not a dead-metal corner).
  std::vector<StickNode> exact_stick_nodes() const;
  /// The directions a stuck node's step constraints hold, orthonormal on its free dofs,
  /// with their targets (solvers/exact_stick.hpp): the tangents restricted to the free
  /// dofs (unchanged where all are free).
  static std::vector<std::pair<Point<dim>, Real>>
  free_tangents(const StickNode& node, const Point<dim>& normal,
                const std::vector<Point<dim>>& tangents, const Point<dim>& slip);

  assembly::FrictionMultipliers<dim>* friction_ = nullptr;
  std::vector<StickNode> stick_nodes_;
  /// Per constraint of the last step_constraints: its node and tangent.
  mutable std::vector<std::pair<std::size_t, Point<dim>>> constrained_;
  /// The points of the nodes the last constrained step held (take_held_points).
  mutable std::vector<std::size_t> held_points_;
  assembly::UnsymmetricTangent<dim> coupling_;
  /// coupling_ is not empty on some rank: every rank then takes the GMRES path.
  bool coupled_ = false;
  Hook hook_;
  bool hook_changes_ = false;
};

} // namespace formflow::solvers
