// SPDX-License-Identifier: MIT
// Residual and consistent tangent of the regularised penalty problem (eq. 3.19) for Newton.
//
// Two deliberate simplifications keep the tangent symmetric, so that CHOLMOD
// LLᵀ (one symbolic analysis, the pattern of the secant system) still applies:
//  * τ_f is frozen at the start of each Newton step. Its exact derivative
//    couples every contact point to the pressures of its neighbours within the
//    mollifier radius h, an unsymmetric term outside the cell pattern. With it
//    lagged, each step is an exact Newton step of a problem with a convex
//    potential (which the line search uses), and τ_f converges at the rate of
//    a fixed point of μ_f-weighted contact pressure, fast for μ_f ≤ 0.2.
//  * with the paper's full-ε̇ a-form, the exact derivative of ⅔ν(ε̄̇) ε̇(u):ε̇(v)
//    has, besides the symmetric (ė(u):ε̇(v))(ė(u):ε̇(δu)), the unsymmetric part
//    ⅓ ε̇_V(u) ε̇_V(v) (ė(u):ε̇(δu)); ε̇_V(u) = d σ_H is O(d) and that part is
//    dwarfed by the (1/d) ε̇_V ε̇_V penalty, so it is dropped. For the
//    deviatoric form the tangent is exact.
#include "formflow/assembly/forming_problem.hpp"

#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/tangent_kernels.hpp"
#include "formflow/core/error.hpp"
#include "formflow/physics/kinematics.hpp"

namespace formflow::assembly {

template <int dim>
std::vector<Real> FormingProblem<dim>::friction_thresholds(const VectorX& w) const {
  const std::vector<ContactPoint<dim>> state = contact_state(w);
  std::vector<Real> thresholds(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) thresholds[k] = state[k].friction_threshold;
  return thresholds;
}

template <int dim>
void FormingProblem<dim>::assemble_newton(const VectorX& u, std::span<const Real> thresholds,
                                          const NewtonDuals<dim>& duals, LinearSystem& secant,
                                          LinearSystem* tangent) const {
  // Plane strain with regularised friction only: no hoop terms, no multipliers here.
  FF_ASSERT(!axisymmetric() && !has_exact_friction() && !multipliers_,
            "Newton covers the plane regularised penalty problem");
  ScatterPlan::clear(secant);
  if (tangent) ScatterPlan::clear(*tangent);
  std::vector<ContactPoint<dim>> state = contact_state(u);
  const bool with_friction = settings_.friction.mu > 0;
  for (std::size_t k = 0; k < state.size(); ++k) {
    state[k].friction_threshold = thresholds[k];
    state[k].friction_weight = physics::friction_weight(
        thresholds[k], state[k].tangential_velocity.norm(), settings_.friction.d_t);
  }

  fem::CellValues<dim> full_values(mesh_.order, full_rule_);
  fem::CellValues<dim> volumetric_values(mesh_.order, volumetric_rule_);
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  const int n_local = mesh_.nodes_per_cell() * dim;
  MatrixX local_secant(n_local, n_local), local_tangent(n_local, n_local);
  VectorX unused_load = VectorX::Zero(n_local);  // loads come only from mixed multipliers
  const int n_q = full_rule_.size(), n_face_q = facet_rule_.size();
  std::vector<Real> viscosity(n_q), coefficient_a(n_q), coefficient_b(n_q);
  std::vector<Tensor3> deviators(n_q), cell_duals(n_q);
  std::vector<Point<dim>> slip(n_face_q), dual_slip(n_face_q);
  std::vector<Real> friction_coefficient(n_face_q);

  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
    gather(cell, &u, coordinates, velocities);
    full_values.reinit(coordinates);
    volumetric_values.reinit(coordinates);
    for (int q = 0; q < n_q; ++q) {
      const Tensor3 rate = physics::strain_rate<dim>(
          physics::velocity_gradient<dim>(velocities, full_values.gradients(q)));
      const Real eps_bar_dot = physics::equivalent_strain_rate(rate);
      viscosity[q] = settings_.law.secant_viscosity(eps_bar_dot);
      deviators[q] = physics::deviator(rate);
      cell_duals[q] = duals.empty() ? Tensor3(viscosity[q] * deviators[q]) : duals.stress[cell * n_q + q];
      // a = (4/9) σ_p′/ε̄̇², b = −(4/9)/ε̄̇² (kernels/tangent_kernels.hpp); at ε̄̇ = 0 the
      // law is on its linear branch and the secant matrix is already the tangent.
      const Real scale = eps_bar_dot > 0 ? 4.0 / 9.0 / (eps_bar_dot * eps_bar_dot) : 0.0;
      coefficient_a[q] = scale * settings_.law.yield_stress_derivative(eps_bar_dot);
      coefficient_b[q] = -scale;
    }
    local_secant.setZero();
    add_viscous_term<dim>(full_values, viscosity, settings_.viscous_strain, local_secant);
    add_volumetric_penalty<dim>(volumetric_values, settings_.penalty.d, local_secant);
    assemble_contact(cell, with_friction ? &state : nullptr, coordinates, facet_values, local_secant,
                     unused_load);
    plan_->scatter(cell, local_secant, constraints_.values, secant);
    if (!tangent) continue;

    local_tangent = local_secant;
    add_viscous_tangent<dim>(full_values, deviators, cell_duals, coefficient_a, coefficient_b,
                             local_tangent);
    for (Index k = cell_contact_offsets_[cell]; with_friction && k < cell_contact_offsets_[cell + 1];
         ++k) {
      const Index position = cell_contact_[k];
      reinit_contact(facet_values, coordinates, position);
      for (int q = 0; q < n_face_q; ++q) {
        const Index k = position * n_face_q + q;
        const ContactPoint<dim>& point = state[k];
        const Real slip_speed = point.tangential_velocity.norm();
        const Real s2 = slip_speed * slip_speed + settings_.friction.d_t * settings_.friction.d_t;
        slip[q] = point.tangential_velocity;
        dual_slip[q] = duals.empty() ? slip[q] : Point<dim>(std::sqrt(s2) * duals.slip[k]);
        friction_coefficient[q] = point.friction_threshold / (s2 * std::sqrt(s2));  // τ_f/s³
      }
      add_friction_tangent<dim>(facet_values, slip, dual_slip, friction_coefficient, local_tangent);
    }
    plan_->scatter(cell, local_tangent, constraints_.values, *tangent);
  }
}

template <int dim>
void FormingProblem<dim>::update_slip_duals(const VectorX& u, const VectorX& step, bool primal,
                                            std::vector<Point<dim>>& slip_duals) const {
  const std::vector<ContactPoint<dim>> state = contact_state(u), change = contact_state(step);
  slip_duals.resize(state.size());
  const Real d_t = settings_.friction.d_t;
  for (std::size_t k = 0; k < state.size(); ++k) {
    const Point<dim>& slip = state[k].tangential_velocity;
    const Point<dim>& slip_change = change[k].tangential_velocity;
    const Real s = std::sqrt(slip.squaredNorm() + d_t * d_t);
    Point<dim>& lambda = slip_duals[k];
    if (primal) lambda = slip / s;
    // Newton on s λ − u_T = 0: λ + δλ = (u_T + δu_T)/s − λ (u_T·δu_T)/s².
    lambda = (slip + slip_change) / s - lambda * (slip.dot(slip_change) / (s * s));
    if (lambda.norm() > 1.0) lambda.normalize();
  }
}

template <int dim>
void FormingProblem<dim>::update_duals(const VectorX& u, const VectorX& step, const VectorX& next,
                                       NewtonDuals<dim>& all_duals) const {
  const int n_q = full_rule_.size();
  const bool primal = all_duals.empty();
  update_slip_duals(u, step, primal, all_duals.slip);
  std::vector<Tensor3>& duals = all_duals.stress;
  duals.resize(static_cast<std::size_t>(mesh_.n_cells()) * n_q);
  fem::CellValues<dim> values(mesh_.order, full_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, velocities, step_velocities, next_velocities;
  const physics::FlowLaw& law = settings_.law;
  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
    gather(cell, &u, coordinates, velocities);
    gather(cell, &step, coordinates, step_velocities);
    gather(cell, &next, coordinates, next_velocities);
    values.reinit(coordinates);
    for (int q = 0; q < n_q; ++q) {
      const auto& grad = values.gradients(q);
      const Tensor3 next_dev = physics::deviator(
          physics::strain_rate<dim>(physics::velocity_gradient<dim>(next_velocities, grad)));
      const Real next_eps = std::sqrt(2.0 / 3.0 * next_dev.squaredNorm());
      Tensor3& w = duals[cell * n_q + q];
      // Where the law is linear the dual stress is just ν ė: nothing to gain.
      if (next_eps <= law.rate1 || next_eps >= law.rate2) {
        w = law.secant_viscosity(next_eps) * next_dev;
        continue;
      }
      const Tensor3 dev = physics::deviator(
          physics::strain_rate<dim>(physics::velocity_gradient<dim>(velocities, grad)));
      const Real eps = std::sqrt(2.0 / 3.0 * dev.squaredNorm());
      const Real nu = law.secant_viscosity(eps);
      if (primal) w = nu * dev;
      if (eps > 0) {
        // Newton on ε̄̇ w − σ_p(ε̄̇) ė = 0 at (u, w) along the step:
        // w + δw = ν ė + ν ė(δu) + (σ_p′ ė − w) dε̄̇/ε̄̇.
        const Tensor3 step_dev = physics::deviator(
            physics::strain_rate<dim>(physics::velocity_gradient<dim>(step_velocities, grad)));
        const Real rate_change = 2.0 / 3.0 * dev.cwiseProduct(step_dev).sum() / eps;  // dε̄̇
        w = nu * (dev + step_dev) + (law.yield_stress_derivative(eps) * dev - w) * (rate_change / eps);
      } else {
        w = law.secant_viscosity(next_eps) * next_dev;
      }
      const Real cap = law.yield_stress(next_eps);
      const Real size = std::sqrt(2.0 / 3.0 * w.squaredNorm());
      if (size > cap) w *= cap / size;
    }
  }
}

template void FormingProblem<2>::update_duals(const VectorX&, const VectorX&, const VectorX&,
                                              NewtonDuals<2>&) const;
template void FormingProblem<3>::update_duals(const VectorX&, const VectorX&, const VectorX&,
                                              NewtonDuals<3>&) const;
template std::vector<Real> FormingProblem<2>::friction_thresholds(const VectorX&) const;
template std::vector<Real> FormingProblem<3>::friction_thresholds(const VectorX&) const;
template void FormingProblem<2>::assemble_newton(const VectorX&, std::span<const Real>,
                                                 const NewtonDuals<2>&, LinearSystem&,
                                                 LinearSystem*) const;
template void FormingProblem<3>::assemble_newton(const VectorX&, std::span<const Real>,
                                                 const NewtonDuals<3>&, LinearSystem&,
                                                 LinearSystem*) const;

}  // namespace formflow::assembly
