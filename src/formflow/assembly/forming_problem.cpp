// SPDX-License-Identifier: MIT
// Cell and contact-face loops of the secant system K(w) u = F.
#include "formflow/assembly/forming_problem.hpp"

#include "formflow/assembly/kernels/fixed_size.hpp"
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/physics/kinematics.hpp"

namespace formflow::assembly {

namespace {

bool friction_acts_on(const physics::Friction& friction, mesh::BoundaryLabel label) {
  if (physics::friction_vanishes(friction)) return false;
  return (label == mesh::BoundaryLabel::Container && friction.on_container) ||
         (label == mesh::BoundaryLabel::Die && friction.on_die);
}

} // namespace

/// Alart–Curnier friction at one point, λ_new = proj(λ + r u_T) = s (λ + r u_T), written
/// for the secant system as the penalty s·r on u_T and the load s·λ, both frozen at the
/// current iterate. Only the tangential part of λ counts (the normal is fixed, but a
/// multiplier handed in from elsewhere need not be tangential).
template <int dim>
void exact_friction_point(const Point<dim>& multiplier, Real augmentation,
                          ContactPoint<dim>& point) {
  const Point<dim> lambda = multiplier - multiplier.dot(point.normal) * point.normal;
  const Point<dim> trial = lambda + augmentation * point.tangential_velocity;
  const Real s = physics::coulomb_projection_factor(point.friction_threshold, trial.norm());
  point.friction_weight = s * augmentation;
  point.friction_load = s * lambda;
  point.friction_traction = s * trial;
  point.sticking = point.friction_threshold > 0 && trial.norm() <= point.friction_threshold;
}

template void exact_friction_point<2>(const Point<2>&, Real, ContactPoint<2>&);
template void exact_friction_point<3>(const Point<3>&, Real, ContactPoint<3>&);

template <int dim>
FormingProblem<dim>::FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings)
    : FormingProblem(mesh, settings, make_process_constraints(mesh, settings.process), {}) {}

template <int dim>
FormingProblem<dim>::FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings,
                                    DirichletConstraints constraints, BodyForce<dim> body_force)
    : mesh_(mesh), settings_(settings), body_force_(std::move(body_force)),
      discretisation_(std::make_unique<Discretisation<dim>>(
          mesh,
          DiscretisationSettings{settings.symmetry, settings.volumetric_points, settings.contact,
                                 settings.friction.radius},
          std::move(constraints))) {}

template <int dim>
std::vector<ContactPoint<dim>>
FormingProblem<dim>::contact_state(const VectorX& u,
                                   const FrictionMultipliers<dim>* multipliers) const {
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  std::vector<ContactPoint<dim>> state;
  state.reserve(discretisation_->contact_facets().size() * facet_rule().size());
  // The Tresca and hybrid thresholds read the flow stress at the surface point, taken
  // at max(ε̄̇, rate1): below rate1 the law's linear continuation would make a rigid
  // billet frictionless.
  const bool shear_yield = physics::needs_shear_yield(settings_.friction);
  for (Index position = 0; position < static_cast<Index>(discretisation_->contact_facets().size());
       ++position) {
    const Index f = discretisation_->contact_facets()[position];
    const mesh::BoundaryFacet& facet = mesh_.facets[f];
    gather(facet.cell, &u, coordinates, velocities);
    reinit_contact(facet_values, coordinates, position);
    for (int q = 0; q < facet_values.n_points(); ++q) {
      ContactPoint<dim> point;
      point.facet = f;
      point.position = facet_values.point(q);
      point.normal = facet_values.normal(q);
      point.weight = facet_values.JxW(q);
      const Point<dim> velocity = velocities * facet_values.shape(q);
      point.normal_velocity = velocity.dot(point.normal);
      point.tangential_velocity = velocity - point.normal_velocity * point.normal;
      point.contact_pressure =
          multipliers_ ? multipliers_->contact_pressure(static_cast<Index>(state.size()),
                                                        point.normal_velocity)
                       : point.normal_velocity / settings_.penalty.d_n; // −σ_N (eq. 3.6)
      if (shear_yield) {
        const Real rate =
            physics::equivalent_strain_rate(strain_rate_at(facet_values, velocities, q));
        point.shear_yield =
            settings_.law.yield_stress(std::max(rate, settings_.law.rate1)) / std::sqrt(3.0);
      }
      state.push_back(point);
    }
  }

  std::vector<Real> pressure(state.size()), mean;
  for (std::size_t k = 0; k < state.size(); ++k) pressure[k] = state[k].contact_pressure;
  discretisation_->mollifier().apply(pressure, mean);
  for (std::size_t k = 0; k < state.size(); ++k) {
    ContactPoint<dim>& point = state[k];
    point.mean_contact_pressure = mean[k];
    if (!friction_acts_on(settings_.friction, mesh_.facets[point.facet].label)) continue;
    const physics::ThresholdValue threshold =
        physics::friction_threshold(settings_.friction, {mean[k], point.shear_yield});
    point.friction_threshold = threshold.value;
    point.threshold_pressure_slope = threshold.pressure_slope;
    const Real slip = point.tangential_velocity.norm();
    if (has_exact_friction()) {
      const bool given = multipliers && !multipliers->traction.empty();
      FF_ASSERT(!given || multipliers->traction.size() == state.size(), "one multiplier per point");
      const Point<dim> lambda = given ? multipliers->traction[k] : Point<dim>::Zero();
      exact_friction_point(lambda, augmentation(), point);
      continue;
    }
    point.friction_weight =
        physics::friction_weight(point.friction_threshold, slip, settings_.friction.d_t);
    point.friction_traction = point.friction_weight * point.tangential_velocity;
    point.sticking =
        physics::is_sticking_regularized(point.friction_threshold, slip, settings_.friction.d_t);
  }
  return state;
}

template <int dim>
void FormingProblem<dim>::assemble(const VectorX* w, LinearSystem& system,
                                   const FrictionMultipliers<dim>* multipliers) const {
  ScatterPlan::clear(system);
  const bool with_friction = w && !physics::friction_vanishes(settings_.friction);
  std::vector<ContactPoint<dim>> state;
  if (with_friction) state = contact_state(*w, multipliers);

  fem::CellValues<dim> full_values(mesh_.order, full_rule());
  fem::CellValues<dim> volumetric_values(mesh_.order, volumetric_rule());
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule());
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  const int n_local = mesh_.nodes_per_cell() * dim;
  MatrixX local_matrix(n_local, n_local);
  VectorX local_load(n_local);
  std::vector<Real> viscosity(full_rule().size());
  const Real initial_viscosity = settings_.law.secant_viscosity(settings_.initial_rate);

  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
    gather(cell, w, coordinates, velocities);
    load_cell(cell, full_values, &volumetric_values);
    for (int q = 0; q < full_values.n_points(); ++q) {
      if (!w) {
        viscosity[q] = initial_viscosity;
        continue;
      }
      const Tensor3 rate = strain_rate_at(full_values, velocities, q);
      viscosity[q] = settings_.law.secant_viscosity(physics::equivalent_strain_rate(rate));
    }
    local_matrix.setZero();
    local_load.setZero();
    add_viscous_term<dim>(full_values, viscosity, settings_.viscous_strain, local_matrix);
    if constexpr (dim == 2) {
      if (axisymmetric()) {
        add_hoop_viscous_term(full_values, viscosity, settings_.viscous_strain, local_matrix);
        add_volumetric_penalty_axisymmetric(volumetric_values, settings_.penalty.d, local_matrix);
      }
    }
    if (multipliers_ && multipliers_->has_pressure_space())
      multipliers_->add_cell_terms(cell, viscosity, local_matrix, local_load);
    else if (!axisymmetric())
      add_volumetric_penalty<dim>(volumetric_values, settings_.penalty.d, local_matrix);
    assemble_contact(cell, with_friction ? &state : nullptr, coordinates, facet_values,
                     local_matrix, local_load);
    plan().scatter(cell, local_matrix, constraints().values, system);
    if (multipliers_ && multipliers_->has_cell_loads()) scatter_load(cell, local_load, system);
    if (with_friction && has_exact_friction())
      add_friction_loads(cell, state, coordinates, facet_values, system);
    if (body_force_) {
      add_body_force(full_values, local_load);
      plan().scatter_load(cell, local_load, system);
    }
  }
}

template <int dim>
void FormingProblem<dim>::add_body_force(const fem::CellValues<dim>& values,
                                         VectorX& local_load) const {
  local_load.setZero(values.n_nodes() * dim);
  for (int q = 0; q < values.n_points(); ++q) {
    const Point<dim> force = body_force_(values.point(q));
    for (int a = 0; a < values.n_nodes(); ++a) // ∫ f·φ_a e_i dx
      local_load.template segment<dim>(a * dim) += values.shape(q)[a] * values.JxW(q) * force;
  }
}

template <int dim>
void FormingProblem<dim>::add_friction_loads(
    Index cell, const std::vector<ContactPoint<dim>>& state,
    const typename fem::CellValues<dim>::Gradients& coordinates,
    fem::FacetValues<dim>& facet_values, LinearSystem& system) const {
  // The friction load moves to the right-hand side: F −= ∫_Γ3 s λ_T·v dΓ. On
  // prescribed dofs (the ram corner of the container wall) it is part of the reaction.
  const int n_q = facet_rule().size();
  for (const Index position : discretisation_->cell_contact_faces(cell)) {
    reinit_contact(facet_values, coordinates, position);
    for (int q = 0; q < n_q; ++q) {
      const ContactPoint<dim>& point = state[position * n_q + q];
      if (point.friction_load.isZero(0.0)) continue;
      for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
        for (int i = 0; i < dim; ++i) {
          const Real load = point.friction_load[i] * facet_values.shape(q)[a] * facet_values.JxW(q);
          const Index dof = fem::dof_of<dim>(mesh_.cells(a, cell), i);
          if (const Index row = plan().free_index(dof); row >= 0)
            system.rhs[row] -= load;
          else
            system.prescribed_loads[plan().prescribed_index(dof)] -= load;
        }
    }
  }
}

template <int dim>
void FormingProblem<dim>::assemble_contact(
    Index cell, const std::vector<ContactPoint<dim>>* state,
    const typename fem::CellValues<dim>::Gradients& coordinates,
    fem::FacetValues<dim>& facet_values, MatrixX& local_matrix, VectorX& local_load) const {
  const int n_q = facet_rule().size();
  std::vector<Real> weight(n_q, 0.0);
  for (const Index position : discretisation_->cell_contact_faces(cell)) {
    reinit_contact(facet_values, coordinates, position);
    if (multipliers_ && multipliers_->is_exact_contact())
      multipliers_->add_contact_terms(position * n_q, facet_values, local_matrix, local_load);
    else
      add_contact_penalty<dim>(facet_values, settings_.penalty.d_n, local_matrix);
    if (!state) continue;
    for (int q = 0; q < n_q; ++q) weight[q] = (*state)[position * n_q + q].friction_weight;
    add_friction_term<dim>(facet_values, weight, local_matrix);
  }
}

template <int dim>
void FormingProblem<dim>::scatter_load(Index cell, const VectorX& local_load,
                                       LinearSystem& system) const {
  for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
    for (int i = 0; i < dim; ++i) {
      const Index dof = fem::dof_of<dim>(mesh_.cells(a, cell), i);
      const Real load = local_load[a * dim + i];
      if (const Index free = plan().free_index(dof); free >= 0)
        system.rhs[free] += load;
      else
        system.prescribed_loads[plan().prescribed_index(dof)] += load;
    }
}

template <int dim>
Real FormingProblem<dim>::driven_force(const LinearSystem& system, const VectorX& u) const {
  const VectorX reactions = system.reaction_rows * u;
  Real force = 0.0;
  for (Index dof : constraints().driven_dofs) {
    const Index row = plan().prescribed_index(dof);
    force += reactions[row] - system.prescribed_loads[row];
  }
  return force;
}

template class FormingProblem<2>;
template class FormingProblem<3>;

} // namespace formflow::assembly
