// SPDX-License-Identifier: MIT
// The forming problem's Newton pieces and Uzawa updates behind the drivers' interface.
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/newton_duals.hpp"

#include <vector>

namespace formflow::solvers {

namespace {

/// The forming problem's duals (assembly::NewtonDuals) as the drivers' opaque state.
template <int dim> struct FormingDuals final : DualState {
  assembly::NewtonDuals<dim> value;
  std::unique_ptr<DualState> clone() const override {
    return std::make_unique<FormingDuals>(*this);
  }
};

// Every DualState this adapter receives was made by its make_duals.
template <int dim> const assembly::NewtonDuals<dim>& duals_of(const DualState& duals) {
  return static_cast<const FormingDuals<dim>&>(duals).value;
}
template <int dim> assembly::NewtonDuals<dim>& duals_of(DualState& duals) {
  return static_cast<FormingDuals<dim>&>(duals).value;
}

} // namespace

template <int dim> std::unique_ptr<DualState> FormingNonlinearProblem<dim>::make_duals() const {
  return std::make_unique<FormingDuals<dim>>();
}

template <int dim>
void FormingNonlinearProblem<dim>::assemble_newton(const VectorX& u, const DualState& duals,
                                                   VectorX& internal_force,
                                                   assembly::LinearSystem* tangent) {
  problem_.assemble_newton(u, problem_.friction_thresholds(u), duals_of<dim>(duals), internal_force,
                           tangent, tangent ? &coupling_ : nullptr, friction_);
}

template <int dim>
void FormingNonlinearProblem<dim>::update_duals(const VectorX& u, const VectorX& step,
                                                const VectorX& next, DualState& duals) const {
  solvers::update_duals(problem_, u, step, next, duals_of<dim>(duals), friction_);
}

template <int dim>
void FormingNonlinearProblem<dim>::secant_duals(const VectorX* previous, const VectorX& next,
                                                DualState& duals) const {
  solvers::secant_duals(problem_, previous, next, duals_of<dim>(duals), friction_);
}

template <int dim> std::optional<UzawaLimits> FormingNonlinearProblem<dim>::uzawa_limits() const {
  const assembly::ConstraintMultipliers<dim>* multipliers = problem_.multipliers();
  if (!multipliers || !multipliers->needs_uzawa()) return std::nullopt;
  const assembly::Formulation& formulation = multipliers->formulation();
  return UzawaLimits{formulation.uzawa_tolerance, formulation.uzawa_max_steps};
}

template <int dim>
Real FormingNonlinearProblem<dim>::update_constraint_multipliers(const VectorX& velocity) {
  assembly::ConstraintMultipliers<dim>& multipliers = *problem_.multipliers();
  std::vector<Real> normal_velocity;
  if (multipliers.is_exact_contact())
    for (const auto& point : problem_.contact_state(velocity))
      normal_velocity.push_back(point.normal_velocity);
  return multipliers.update(velocity, normal_velocity);
}

template class FormingNonlinearProblem<2>;
template class FormingNonlinearProblem<3>;

} // namespace formflow::solvers
