// SPDX-License-Identifier: MIT
// Newton's passes of the one assembly loop (assembly/assembler.hpp) and the matrix-free
// rest of its Jacobian. The exact Jacobian is split as J = T + N so that CHOLMOD LLᵀ
// (one symbolic analysis, the pattern of the secant system) still applies to T:
//  * T: the secant matrix plus each term's symmetric derivative (the viscous term in
//    primal–dual form, friction at fixed τ_f); for the deviatoric a-form without
//    friction T is the whole Jacobian.
//  * N (UnsymmetricTangent, applied matrix free; the solver uses GMRES with T⁻¹): the
//    full-ε̇ a-form's ν′ ε̇_V part (terms/viscous_term.cpp) and dτ_f of a
//    pressure-dependent threshold (terms/friction_term.cpp).
#include "formflow/assembly/forming_problem.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"
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
void FormingProblem<dim>::assemble_newton(
    const VectorX& u, std::span<const Real> thresholds, const NewtonDuals<dim>& duals,
    VectorX& internal_force, LinearSystem* tangent, UnsymmetricTangent<dim>* coupling,
    const FrictionMultipliers<dim>* friction_multipliers) const {
  // The penalty problem, friction regularised or exact with frozen multipliers
  // (null: λ̂ = 0), no loads; the mixed formulation only with its pressure
  // condensed at d > 0 (a fixed matrix per cell: no multiplier loop).
  FF_ASSERT(terms_.newton_ready() && !body_force_,
            "Newton covers the penalty problem and the condensed mixed one");
  FF_ASSERT(!coupling || tangent, "the coupling is part of the tangent");
  internal_force.setZero(n_dofs());
  if (tangent) ScatterPlan::clear(*tangent);
  if (coupling) {
    coupling->clear();
    coupling->n_local = mesh_.nodes_per_cell() * dim;
  }
  // The contact state at u; the face terms freeze τ_f at `thresholds` in it and give
  // the threshold's coupling (terms/friction_term.cpp).
  std::vector<ContactPoint<dim>> state = contact_state(u, friction_multipliers);
  const bool given = friction_multipliers && !friction_multipliers->traction.empty();
  NewtonPass<dim> pass{state, thresholds,
                       given ? std::span<const Point<dim>>(friction_multipliers->traction)
                             : std::span<const Point<dim>>(),
                       coupling};
  for (const auto& term : terms_.face) term->begin_newton(pass);
  // Without friction no face term reads the state (the contact penalty needs u only).
  const bool with_friction = !physics::friction_vanishes(settings_.friction);

  AssemblyRequest<dim> request;
  request.pass = tangent ? AssemblyPass::Tangent : AssemblyPass::Force;
  request.velocity = &u;
  if (with_friction) request.contact = state;
  request.duals = &duals;
  request.coupling = coupling;
  ScatterSink<dim> sink(mesh_, plan(), constraints().values, tangent, &internal_force);
  assembler_->run(request, &sink);
}

template <int dim>
void FormingProblem<dim>::apply_coupling(const UnsymmetricTangent<dim>& coupling,
                                         const VectorX& x_free, VectorX& y_free) const {
  const int n_local = coupling.n_local, n_nodes = mesh_.nodes_per_cell();
  std::vector<Index> rows(n_local);
  CellVector x_local(n_local);
  Index last_cell = -1;
  for (std::size_t k = 0; k < coupling.cells.size(); ++k) {
    const Index cell = coupling.cells[k];
    if (cell != last_cell) { // points of one cell are stored together
      for (int a = 0; a < n_nodes; ++a)
        for (int i = 0; i < dim; ++i) {
          const Index row = plan().free_index(fem::dof_of<dim>(mesh_.cells(a, cell), i));
          rows[a * dim + i] = row;
          x_local[a * dim + i] = row >= 0 ? x_free[row] : 0.0;
        }
      last_cell = cell;
    }
    const Real* divergence = coupling.rows.data() + 2 * k * n_local;
    const Real* deviator = divergence + n_local;
    Real g = 0.0;
    for (int l = 0; l < n_local; ++l) g += deviator[l] * x_local[l];
    g *= coupling.coefficients[k];
    for (int l = 0; l < n_local; ++l)
      if (rows[l] >= 0) y_free[rows[l]] += g * divergence[l];
  }
  if (!coupling.has_friction) return;

  // dσ̄_N[x] is the mollified u_N(x)/d_N: contact_state of x itself (it is linear in x).
  const std::vector<ContactPoint<dim>> change =
      contact_state(plan().expand(x_free, VectorX::Zero(n_dofs())));
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule());
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  const int n_face_q = facet_rule().size();
  for (std::size_t position = 0; position < discretisation_->contact_facets().size(); ++position) {
    const mesh::BoundaryFacet& facet = mesh_.facets[discretisation_->contact_facets()[position]];
    gather(facet.cell, nullptr, coordinates, unused);
    reinit_contact(facet_values, coordinates, static_cast<Index>(position));
    for (int q = 0; q < n_face_q; ++q) {
      const std::size_t k = position * n_face_q + q;
      if (coupling.threshold_slip[k].isZero(0.0)) continue;
      const Point<dim> traction =
          (change[k].mean_contact_pressure * facet_values.JxW(q)) * coupling.threshold_slip[k];
      for (int a = 0; a < n_nodes; ++a)
        for (int i = 0; i < dim; ++i) {
          const Index row = plan().free_index(fem::dof_of<dim>(mesh_.cells(a, facet.cell), i));
          if (row >= 0) y_free[row] += facet_values.shape(q)[a] * traction[i];
        }
    }
  }
}

template <int dim> Real FormingProblem<dim>::driven_force(const VectorX& internal_force) const {
  Real force = 0.0;
  for (Index dof : constraints().driven_dofs) force += internal_force[dof];
  return force;
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
std::vector<Point<dim>>
FormingProblem<dim>::trial_tractions(const std::vector<ContactPoint<dim>>& state,
                                     const FrictionMultipliers<dim>* friction_multipliers) const {
  const bool given = friction_multipliers && !friction_multipliers->traction.empty();
  std::vector<Point<dim>> trial(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) {
    const Point<dim>& n = state[k].normal;
    const Point<dim> lambda = given ? Point<dim>(friction_multipliers->traction[k] -
                                                 friction_multipliers->traction[k].dot(n) * n)
                                    : Point<dim>::Zero();
    trial[k] = lambda + augmentation() * state[k].tangential_velocity;
  }
  return trial;
}

template <int dim>
void FormingProblem<dim>::update_exact_slip_duals(
    const VectorX& u, const VectorX& step, bool primal,
    const FrictionMultipliers<dim>* friction_multipliers,
    std::vector<Point<dim>>& slip_duals) const {
  const std::vector<ContactPoint<dim>> state = contact_state(u), change = contact_state(step);
  const std::vector<Point<dim>> trial = trial_tractions(state, friction_multipliers);
  slip_duals.resize(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) {
    Point<dim>& lambda = slip_duals[k];
    const Real threshold = state[k].friction_threshold;
    if (threshold <= 0) {
      lambda.setZero();
      continue;
    }
    const Point<dim> trial_change = augmentation() * change[k].tangential_velocity; // δt
    const Real size = trial[k].norm();
    if (size <= threshold) {
      lambda = (trial[k] + trial_change) / threshold; // stick: λ = t/τ_f is linear in t
    } else {
      if (primal) lambda = trial[k] / size;
      // Newton on |t| λ − t = 0: λ + δλ = (t + δt)/|t| − λ (t·δt)/|t|².
      lambda =
          (trial[k] + trial_change) / size - lambda * (trial[k].dot(trial_change) / (size * size));
    }
    if (lambda.norm() > 1.0) lambda.normalize();
  }
}

template <int dim>
void FormingProblem<dim>::update_duals(const VectorX& u, const VectorX& step, const VectorX& next,
                                       NewtonDuals<dim>& all_duals,
                                       const FrictionMultipliers<dim>* friction_multipliers) const {
  const int n_q = full_rule().size();
  const bool primal = all_duals.empty();
  if (has_exact_friction())
    update_exact_slip_duals(u, step, primal, friction_multipliers, all_duals.slip);
  else
    update_slip_duals(u, step, primal, all_duals.slip);
  std::vector<Tensor3>& duals = all_duals.stress;
  duals.resize(static_cast<std::size_t>(mesh_.n_cells()) * n_q);
  fem::CellValues<dim> values(mesh_.order, full_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities, step_velocities,
      next_velocities;
  const physics::FlowLaw& law = settings_.law;
  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
    gather(cell, &u, coordinates, velocities);
    gather(cell, &step, coordinates, step_velocities);
    gather(cell, &next, coordinates, next_velocities);
    load_cell(cell, values, nullptr);
    for (int q = 0; q < n_q; ++q) {
      const Tensor3 next_dev = physics::deviator(strain_rate_at(values, next_velocities, q));
      const Real next_eps = std::sqrt(2.0 / 3.0 * next_dev.squaredNorm());
      Tensor3& w = duals[cell * n_q + q];
      // Where the law is linear the dual stress is just ν ė: nothing to gain.
      if (law.is_linear_at(next_eps)) {
        w = law.secant_viscosity(next_eps) * next_dev;
        continue;
      }
      const Tensor3 dev = physics::deviator(strain_rate_at(values, velocities, q));
      const Real eps = std::sqrt(2.0 / 3.0 * dev.squaredNorm());
      const auto [nu, nu_derivative] = law.secant_viscosity_and_derivative(eps);
      if (primal) w = nu * dev;
      if (eps > 0) {
        // Newton on ε̄̇ w − σ_p(ε̄̇) ė = 0 at (u, w) along the step:
        // w + δw = ν ė + ν ė(δu) + (σ_p′ ė − w) dε̄̇/ε̄̇.
        const Tensor3 step_dev = physics::deviator(strain_rate_at(values, step_velocities, q));
        const Real rate_change = 2.0 / 3.0 * dev.cwiseProduct(step_dev).sum() / eps; // dε̄̇
        w = nu * (dev + step_dev) + (nu_derivative * dev - w) * (rate_change / eps);
      } else {
        w = law.secant_viscosity(next_eps) * next_dev;
      }
      const Real cap = law.yield_stress(next_eps);
      const Real size = std::sqrt(2.0 / 3.0 * w.squaredNorm());
      if (size > cap) w *= cap / size;
    }
  }
}

template <int dim>
void FormingProblem<dim>::secant_duals(const VectorX* previous, const VectorX& next,
                                       NewtonDuals<dim>& all_duals,
                                       const FrictionMultipliers<dim>* friction_multipliers) const {
  const int n_q = full_rule().size();
  std::vector<Tensor3>& duals = all_duals.stress;
  duals.resize(static_cast<std::size_t>(mesh_.n_cells()) * n_q);
  fem::CellValues<dim> values(mesh_.order, full_rule());
  typename fem::CellValues<dim>::Gradients coordinates, previous_velocities, next_velocities;
  const physics::FlowLaw& law = settings_.law;
  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
    if (previous) gather(cell, previous, coordinates, previous_velocities);
    gather(cell, &next, coordinates, next_velocities);
    load_cell(cell, values, nullptr);
    for (int q = 0; q < n_q; ++q) {
      const Tensor3 next_dev = physics::deviator(strain_rate_at(values, next_velocities, q));
      const Real next_eps = std::sqrt(2.0 / 3.0 * next_dev.squaredNorm());
      Tensor3& w = duals[cell * n_q + q];
      if (law.is_linear_at(next_eps)) { // linear law: w = ν ė exactly
        w = law.secant_viscosity(next_eps) * next_dev;
        continue;
      }
      const Real previous_eps =
          previous ? physics::equivalent_strain_rate(strain_rate_at(values, previous_velocities, q))
                   : settings_.initial_rate;
      // The stress the secant solve balanced, ν(uⁿ⁻¹) ė(uⁿ), capped to the yield surface.
      w = law.secant_viscosity(previous_eps) * next_dev;
      const Real cap = law.yield_stress(next_eps);
      const Real size = std::sqrt(2.0 / 3.0 * w.squaredNorm());
      if (size > cap) w *= cap / size;
    }
  }
  // The slip direction the secant solve used, u_T(uⁿ)/s(uⁿ⁻¹), capped to |λ| ≤ 1.
  // The constant-viscosity solve had no friction (τ_f(0) = 0): λ = 0 there.
  const std::vector<ContactPoint<dim>> after = contact_state(next);
  const std::vector<ContactPoint<dim>> before = previous ? contact_state(*previous) : after;
  const Real d_t = settings_.friction.d_t;
  all_duals.slip.assign(after.size(), Point<dim>::Zero());
  if (has_exact_friction()) {
    // The traction that secant step used over τ_f: s(previous) t(next)/τ_f = t(next)/max(τ_f,
    // |t|)(previous).
    if (!previous) return;
    const std::vector<Point<dim>> trial_after = trial_tractions(after, friction_multipliers);
    const std::vector<Point<dim>> trial_before = trial_tractions(before, friction_multipliers);
    for (std::size_t k = 0; k < after.size(); ++k) {
      const Real threshold = before[k].friction_threshold;
      if (threshold <= 0) continue;
      Point<dim>& lambda = all_duals.slip[k];
      lambda = trial_after[k] / std::max(threshold, trial_before[k].norm());
      if (lambda.norm() > 1.0) lambda.normalize();
    }
    return;
  }
  for (std::size_t k = 0; k < after.size() && previous; ++k) {
    const Real s = std::sqrt(before[k].tangential_velocity.squaredNorm() + d_t * d_t);
    Point<dim>& lambda = all_duals.slip[k];
    lambda = after[k].tangential_velocity / s;
    if (lambda.norm() > 1.0) lambda.normalize();
  }
}

template void FormingProblem<2>::secant_duals(const VectorX*, const VectorX&, NewtonDuals<2>&,
                                              const FrictionMultipliers<2>*) const;
template void FormingProblem<3>::secant_duals(const VectorX*, const VectorX&, NewtonDuals<3>&,
                                              const FrictionMultipliers<3>*) const;
template void FormingProblem<2>::update_duals(const VectorX&, const VectorX&, const VectorX&,
                                              NewtonDuals<2>&, const FrictionMultipliers<2>*) const;
template void FormingProblem<3>::update_duals(const VectorX&, const VectorX&, const VectorX&,
                                              NewtonDuals<3>&, const FrictionMultipliers<3>*) const;
template std::vector<Real> FormingProblem<2>::friction_thresholds(const VectorX&) const;
template std::vector<Real> FormingProblem<3>::friction_thresholds(const VectorX&) const;
template void FormingProblem<2>::assemble_newton(const VectorX&, std::span<const Real>,
                                                 const NewtonDuals<2>&, VectorX&, LinearSystem*,
                                                 UnsymmetricTangent<2>*,
                                                 const FrictionMultipliers<2>*) const;
template void FormingProblem<3>::assemble_newton(const VectorX&, std::span<const Real>,
                                                 const NewtonDuals<3>&, VectorX&, LinearSystem*,
                                                 UnsymmetricTangent<3>*,
                                                 const FrictionMultipliers<3>*) const;
template void FormingProblem<2>::apply_coupling(const UnsymmetricTangent<2>&, const VectorX&,
                                                VectorX&) const;
template void FormingProblem<3>::apply_coupling(const UnsymmetricTangent<3>&, const VectorX&,
                                                VectorX&) const;
template Real FormingProblem<2>::driven_force(const VectorX&) const;
template Real FormingProblem<3>::driven_force(const VectorX&) const;

} // namespace formflow::assembly
