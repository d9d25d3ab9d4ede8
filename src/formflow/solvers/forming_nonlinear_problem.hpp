// SPDX-License-Identifier: MIT
// The forming problem (assembly::FormingProblem) seen through the drivers'
// interface (solvers/nonlinear_problem.hpp).
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"

#include <functional>

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
  void set_friction_multipliers(const assembly::FrictionMultipliers<dim>* multipliers) {
    friction_ = multipliers;
  }
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
  bool has_coupling() const override { return !coupling_.empty(); }
  void apply_coupling(const VectorX& x_free, VectorX& y_free) const override {
    problem_.apply_coupling(coupling_, x_free, y_free);
  }
  void update_duals(const VectorX& u, const VectorX& step, const VectorX& next,
                    DualState& duals) const override;
  void secant_duals(const VectorX* previous, const VectorX& next, DualState& duals) const override;

  /// Uzawa steps when the attached ConstraintMultipliers need them (d = 0 with a
  /// condensed pressure, or d_N = 0).
  std::optional<UzawaLimits> uzawa_limits() const override;
  /// λ ← λ + r M⁻¹B u, λ_N ← λ_N + r_N u_N on the attached ConstraintMultipliers.
  Real update_constraint_multipliers(const VectorX& velocity) override;

  bool changes_after_iteration() const override { return hook_ && hook_changes_; }
  AfterIteration after_iteration(const IterationState& state) override {
    return hook_ ? hook_(state) : AfterIteration{};
  }

private:
  const assembly::FormingProblem<dim>& problem_;
  const assembly::FrictionMultipliers<dim>* friction_ = nullptr;
  assembly::UnsymmetricTangent<dim> coupling_;
  Hook hook_;
  bool hook_changes_ = false;
};

} // namespace formflow::solvers
