// SPDX-License-Identifier: MIT
// Residual and consistent tangent of the penalty problem (eq. 3.19) for Newton, with
// regularised friction or exact friction at frozen multipliers λ̂ (the traction
// proj(λ̂ + r u_T); its semismooth derivative in T, its τ_f derivative in N).
//
// The exact Jacobian is split as J = T + N so that CHOLMOD LLᵀ (one symbolic
// analysis, the pattern of the secant system) still applies to T:
//  * T: the secant matrix plus the symmetric derivative of the viscous term in
//    primal–dual form and of the friction force at fixed τ_f; for the
//    deviatoric a-form without friction T is the whole Jacobian.
//  * N (UnsymmetricTangent, applied matrix free; the solver uses GMRES with T⁻¹):
//    - with the paper's full-ε̇ a-form, the derivative of ⅔ν(ε̄̇) ε̇(u):ε̇(v)
//      has, besides the symmetric (ė(u):ε̇(v))(ė(u):ε̇(δu)), the part
//      ⅓ ε̇_V(u) ε̇_V(v) (ė(u):ε̇(δu)). It is not negligible: in near-rigid zones
//      ν ≈ σ_p(ε̄̇₁)/ε̄̇₁ ≈ 1.7e3, so (2/9)ν ≈ 385 against 1/d = 1000; dropping it
//      made the Newton tail linear (ratio ≈ 0.25 on mesh II).
//    - the derivative of τ_f = μ_f max(σ̄_N, 0): couples each contact point to
//      the normal velocities of its neighbours within the mollifier radius h,
//      outside the cell pattern. Lagging τ_f instead gave a linear tail with
//      friction (mesh II, μ = 0.2: 9 iterations to δ = 1e-4 instead of 8).
#include "formflow/assembly/forming_problem.hpp"

#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/residual_kernels.hpp"
#include "formflow/assembly/kernels/tangent_kernels.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/physics/kinematics.hpp"

namespace formflow::assembly {

namespace {

/// Exact friction's lagged part of the traction on one Γ3 face: ∫ s λ̂_T·φ_a e_i dΓ
/// (the rest, s r u_T, is the friction weight of the contact force/matrix).
template <int dim>
void add_friction_load_force(const fem::FacetValues<dim>& values,
                             const std::vector<ContactPoint<dim>>& state, Index position,
                             CellVector& local_force) {
  const int n_q = values.n_points();
  for (int q = 0; q < n_q; ++q) {
    const Point<dim>& load = state[position * n_q + q].friction_load;
    if (load.isZero(0.0)) continue;
    for (int a = 0; a < static_cast<int>(values.shape(q).size()); ++a)
      local_force.template segment<dim>(a * dim) += (values.shape(q)[a] * values.JxW(q)) * load;
  }
}

} // namespace

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
  FF_ASSERT(!body_force_ && (!multipliers_ || multipliers_->is_condensed_penalty()),
            "Newton covers the penalty problem and the condensed mixed one");
  const bool mixed = multipliers_ != nullptr;
  FF_ASSERT(!coupling || tangent, "the coupling is part of the tangent");
  internal_force.setZero(n_dofs());
  if (tangent) ScatterPlan::clear(*tangent);
  const bool full_strain = settings_.viscous_strain == physics::ViscousStrain::Full;
  if (coupling) {
    coupling->clear();
    coupling->n_local = mesh_.nodes_per_cell() * dim;
  }
  std::vector<ContactPoint<dim>> state = contact_state(u, friction_multipliers);
  const bool with_friction = !physics::friction_vanishes(settings_.friction);
  const bool exact_friction = with_friction && has_exact_friction();
  if (exact_friction) {
    // Exact friction: traction proj(λ̂ + r u_T) at the given τ_f; the coupling
    // keeps dτ_f's direction t̂ = t/|t| at slip points (the projection's τ_f
    // derivative), zero at stick points and where σ̄_N(u) ≤ 0.
    if (coupling) coupling->threshold_slip.assign(state.size(), Point<dim>::Zero());
    const bool given = friction_multipliers && !friction_multipliers->traction.empty();
    for (std::size_t k = 0; k < state.size(); ++k) {
      if (state[k].friction_threshold <= 0 && thresholds[k] <= 0) continue; // friction off here
      const bool own_threshold_positive = state[k].friction_threshold > 0;
      state[k].friction_threshold = thresholds[k];
      exact_friction_point(given ? friction_multipliers->traction[k] : Point<dim>::Zero(),
                           augmentation(), state[k]);
      const bool slipping = thresholds[k] > 0 && !state[k].sticking;
      const Real slope = state[k].threshold_pressure_slope;
      if (!coupling || !slipping || !own_threshold_positive || slope == 0) continue;
      coupling->threshold_slip[k] = slope * state[k].friction_traction.normalized();
      coupling->has_friction = true;
    }
  }
  if (coupling && with_friction && !exact_friction) {
    // dτ_f = (∂τ_f/∂σ̄_N) dσ̄_N where τ_f > 0 (its own σ̄_N at u, read before the
    // given thresholds replace it below): μ_f for Coulomb, 0 for Tresca, whose k(ε̄̇)
    // is lagged (its slope σ_p′/√3 is α σ_p/ε̄̇ small for the rate-insensitive laws
    // and zero below rate1, where the container's rigid billet slides).
    coupling->threshold_slip.assign(state.size(), Point<dim>::Zero());
    for (std::size_t k = 0; k < state.size(); ++k) {
      if (state[k].friction_threshold <= 0 || state[k].threshold_pressure_slope == 0) continue;
      const Real s = std::sqrt(state[k].tangential_velocity.squaredNorm() +
                               settings_.friction.d_t * settings_.friction.d_t);
      coupling->threshold_slip[k] =
          state[k].threshold_pressure_slope / s * state[k].tangential_velocity;
      coupling->has_friction = true;
    }
  }
  for (std::size_t k = 0; k < state.size() && !exact_friction; ++k) {
    state[k].friction_threshold = thresholds[k];
    state[k].friction_weight = physics::friction_weight(
        thresholds[k], state[k].tangential_velocity.norm(), settings_.friction.d_t);
  }

  fem::CellValues<dim> full_values(mesh_.order, full_rule());
  fem::CellValues<dim> volumetric_values(mesh_.order, volumetric_rule());
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  const int n_local = mesh_.nodes_per_cell() * dim;
  MatrixX local_tangent(n_local, n_local);
  CellVector local_force(n_local), divergence_row(n_local), deviator_row(n_local);
  VectorX unused_load(n_local); // contact loads come only from multipliers, absent here
  const int n_q = full_rule().size(), n_face_q = facet_rule().size();
  std::vector<Real> viscosity(n_q), coefficient_a(n_q), coefficient_b(n_q), weight(n_face_q);
  std::vector<Tensor3> rates(n_q), deviators(n_q), cell_duals(n_q);
  std::vector<Point<dim>> slip(n_face_q), dual_slip(n_face_q);
  std::vector<Real> friction_coefficient(n_face_q);

  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
    gather(cell, &u, coordinates, velocities);
    load_cell(cell, full_values, &volumetric_values);
    for (int q = 0; q < n_q; ++q) {
      rates[q] = strain_rate_at(full_values, velocities, q);
      const Real eps_bar_dot = physics::equivalent_strain_rate(rates[q]);
      if (!tangent) {
        viscosity[q] = settings_.law.secant_viscosity(eps_bar_dot);
        continue;
      }
      const auto [secant, derivative] = settings_.law.secant_viscosity_and_derivative(eps_bar_dot);
      viscosity[q] = secant;
      deviators[q] = physics::deviator(rates[q]);
      cell_duals[q] =
          duals.empty() ? Tensor3(viscosity[q] * deviators[q]) : duals.stress[cell * n_q + q];
      // a = (4/9) σ_p′/ε̄̇², b = −(4/9)/ε̄̇² (kernels/tangent_kernels.hpp); at ε̄̇ = 0 the
      // law is on its linear branch and the secant matrix is already the tangent.
      const Real scale = eps_bar_dot > 0 ? 4.0 / 9.0 / (eps_bar_dot * eps_bar_dot) : 0.0;
      coefficient_a[q] = scale * derivative;
      coefficient_b[q] = -scale;
    }
    local_force.setZero(n_local);
    const Eigen::Map<const VectorX> local_velocity(velocities.data(), n_local);
    if (!tangent) {
      // Residual only (line search): from the stresses, no local matrix.
      add_viscous_force<dim>(full_values, viscosity, rates, settings_.viscous_strain, local_force);
      if constexpr (dim == 2) {
        if (axisymmetric()) {
          add_hoop_viscous_force(full_values, viscosity, rates, settings_.viscous_strain,
                                 local_force);
          add_volumetric_force_axisymmetric(volumetric_values, settings_.penalty.d, velocities,
                                            local_force);
        }
      }
      if (mixed)
        multipliers_->add_cell_force(cell, local_velocity, local_force);
      else if (!axisymmetric())
        add_volumetric_force<dim>(volumetric_values, settings_.penalty.d, velocities, local_force);
      for (const Index position : discretisation_->cell_contact_faces(cell)) {
        reinit_contact(facet_values, coordinates, position);
        for (int q = 0; q < n_face_q && with_friction; ++q)
          weight[q] = state[position * n_face_q + q].friction_weight;
        add_contact_force<dim>(
            facet_values, settings_.penalty.d_n, velocities,
            with_friction ? std::span<const Real>(weight) : std::span<const Real>(), local_force);
        if (exact_friction) add_friction_load_force(facet_values, state, position, local_force);
      }
    } else {
      // The secant matrix K_e(u) gives the residual K_e u_e; the tangent adds to it.
      local_tangent.setZero();
      add_viscous_term<dim>(full_values, viscosity, settings_.viscous_strain, local_tangent);
      if constexpr (dim == 2) {
        if (axisymmetric()) {
          add_hoop_viscous_term(full_values, viscosity, settings_.viscous_strain, local_tangent);
          add_volumetric_penalty_axisymmetric(volumetric_values, settings_.penalty.d,
                                              local_tangent);
        }
      }
      unused_load.setZero();
      if (mixed) // (1/d) Bᵀ M⁻¹ B, as in the secant matrix (case validation: plane only)
        multipliers_->add_cell_terms(cell, viscosity, local_tangent, unused_load);
      else if (!axisymmetric())
        add_volumetric_penalty<dim>(volumetric_values, settings_.penalty.d, local_tangent);
      assemble_contact(cell, with_friction ? &state : nullptr, coordinates, facet_values,
                       local_tangent, unused_load);
      local_force.noalias() = local_tangent * local_velocity;
      for (const Index position : discretisation_->cell_contact_faces(cell)) {
        if (!exact_friction) break;
        reinit_contact(facet_values, coordinates, position);
        add_friction_load_force(facet_values, state, position, local_force);
      }
      if constexpr (dim == 2) {
        if (axisymmetric())
          add_viscous_tangent_axisymmetric(full_values, deviators, cell_duals, coefficient_a,
                                           coefficient_b, local_tangent);
      }
      if (!axisymmetric())
        add_viscous_tangent<dim>(full_values, deviators, cell_duals, coefficient_a, coefficient_b,
                                 local_tangent);
      for (const Index position : discretisation_->cell_contact_faces(cell)) {
        if (!with_friction) break;
        reinit_contact(facet_values, coordinates, position);
        for (int q = 0; q < n_face_q && exact_friction; ++q) {
          // Semismooth derivative of proj(t), t = λ̂ + r u_T, at fixed τ_f: r P at
          // stick (the secant term s r P already), s r (P − t̂ t̂ᵀ) at slip: add −s r t̂ t̂ᵀ.
          // Primal–dual as for the regularised law: with the dual λ ≈ t/|t| (the
          // traction over τ_f, |λ| ≤ 1) the slip part is −s r/|t| ½(λ t̂ᵀ + t̂ λᵀ):
          // exact for λ = t̂, PSD with the secant term s r P for any capped λ.
          const ContactPoint<dim>& point = state[position * n_face_q + q];
          const Real trial_norm = point.friction_traction.norm();
          const bool slipping = !point.sticking && point.friction_weight > 0 && trial_norm > 0;
          slip[q] = slipping ? Point<dim>(point.friction_traction) : Point<dim>::Zero();
          dual_slip[q] = duals.empty() || !slipping
                             ? slip[q]
                             : Point<dim>(trial_norm * duals.slip[position * n_face_q + q]);
          friction_coefficient[q] =
              slipping ? point.friction_weight / (trial_norm * trial_norm) : 0.0;
        }
        for (int q = 0; q < n_face_q && !exact_friction; ++q) {
          const ContactPoint<dim>& point = state[position * n_face_q + q];
          const Real slip_speed = point.tangential_velocity.norm();
          const Real s2 = slip_speed * slip_speed + settings_.friction.d_t * settings_.friction.d_t;
          slip[q] = point.tangential_velocity;
          dual_slip[q] = duals.empty()
                             ? slip[q]
                             : Point<dim>(std::sqrt(s2) * duals.slip[position * n_face_q + q]);
          friction_coefficient[q] = point.friction_threshold / (s2 * std::sqrt(s2)); // τ_f/s³
        }
        add_friction_tangent<dim>(facet_values, slip, dual_slip, friction_coefficient,
                                  local_tangent);
      }
      plan().scatter(cell, local_tangent, constraints().values, *tangent);
    }
    for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
      internal_force.template segment<dim>(fem::dof_of<dim>(mesh_.cells(a, cell), 0)) +=
          local_force.template segment<dim>(a * dim);

    // The full-ε̇ form's unsymmetric part (primal: exact at the solution, where the
    // duals are ν ė): ⅔ ν′ dε̄̇[δu] · ⅓ ε̇_V(u) ε̇_V(v) = (a + b ν) ⅓ ε̇_V(u) ε̇_V(v) g(δu).
    if (!coupling || !full_strain) continue;
    for (int q = 0; q < n_q; ++q) {
      const Real c = (coefficient_a[q] + coefficient_b[q] * viscosity[q]) * rates[q].trace() / 3.0;
      if (c == 0.0) continue;
      const auto& grad = full_values.gradients(q);
      const Tensor2<dim> dev = deviators[q].template topLeftCorner<dim, dim>();
      for (int node = 0; node < mesh_.nodes_per_cell(); ++node) {
        divergence_row.template segment<dim>(node * dim) = grad.col(node);
        deviator_row.template segment<dim>(node * dim) = dev * grad.col(node);
        if (axisymmetric()) { // the hoop slot: ε̇_θθ(φ_a e_r) = φ_a/r
          const Real hoop = full_values.shape(q)[node] / full_values.point(q)[1];
          divergence_row[node * dim + 1] += hoop;
          deviator_row[node * dim + 1] += deviators[q](2, 2) * hoop;
        }
      }
      coupling->cells.push_back(cell);
      coupling->coefficients.push_back(c * full_values.JxW(q));
      coupling->rows.insert(coupling->rows.end(), divergence_row.data(),
                            divergence_row.data() + n_local);
      coupling->rows.insert(coupling->rows.end(), deviator_row.data(),
                            deviator_row.data() + n_local);
    }
  }
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
