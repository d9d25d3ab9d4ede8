// SPDX-License-Identifier: MIT
// Cell and contact-face loops of the secant system K(w) u = F.
#include "formflow/assembly/forming_problem.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/physics/kinematics.hpp"

#include <array>

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
  const Point<dim> lambda = point.tangential_part(multiplier);
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
                                 settings.friction.radius, settings.distribution},
          std::move(constraints))) {
  choose_terms();
}

template <int dim>
void FormingProblem<dim>::exchange_contact_values(std::vector<ContactPoint<dim>>& state) const {
  const Distribution& distribution = discretisation_->distribution();
  if (!distribution.distributed()) return;
  // Each Γ3 face is one cell's, so each point's values come from one rank and the
  // others add zeros: every rank gets the owner's bits, the whole contact state on a
  // surface's traffic (the mollifier's average σ̄_N may reach any point).
  constexpr int per_point = dim + 3;
  std::vector<Real> values(state.size() * per_point, 0.0);
  for (std::size_t k = 0; k < state.size(); ++k) {
    if (!discretisation_->assembles(mesh_.facets[state[k].facet].cell)) continue;
    Real* slot = values.data() + k * per_point;
    slot[0] = state[k].normal_velocity;
    slot[1] = state[k].contact_pressure;
    slot[2] = state[k].shear_yield;
    for (int i = 0; i < dim; ++i) slot[3 + i] = state[k].tangential_velocity[i];
  }
  distribution.sum_over_ranks(values);
  for (std::size_t k = 0; k < state.size(); ++k) {
    const Real* slot = values.data() + k * per_point;
    state[k].normal_velocity = slot[0];
    state[k].contact_pressure = slot[1];
    state[k].shear_yield = slot[2];
    for (int i = 0; i < dim; ++i) state[k].tangential_velocity[i] = slot[3 + i];
  }
}

template <int dim>
std::vector<ContactPoint<dim>>
FormingProblem<dim>::contact_state(const VectorX& u,
                                   const FrictionMultipliers<dim>* multipliers) const {
  fem::FacetValues<dim> facet_values(mesh_.cell_type(), facet_rule());
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
    // A distributed run's velocity is ghosted: the rank evaluates the faces of its own
    // cells, and the points' values are exchanged below.
    const bool own = discretisation_->assembles(facet.cell);
    gather(facet.cell, own ? &u : nullptr, coordinates, velocities);
    reinit_contact(facet_values, coordinates, position);
    for (int q = 0; q < facet_values.n_points(); ++q) {
      ContactPoint<dim> point;
      point.facet = f;
      point.position = facet_values.point(q);
      point.normal = facet_values.normal(q);
      point.weight = facet_values.JxW(q);
      if (!own) {
        state.push_back(point);
        continue;
      }
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
        const Real effective = std::max(rate, settings_.law.rate1);
        const std::size_t k = state.size();
        point.shear_yield = (contact_temperatures_.empty()
                                 ? settings_.law.yield_stress(effective)
                                 : physics::FlowLawAt(settings_.law, contact_temperatures_[k])
                                       .yield_stress(effective)) /
                            std::sqrt(3.0);
      }
      state.push_back(point);
    }
  }
  exchange_contact_values(state);

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

template <int dim> void FormingProblem<dim>::choose_terms() {
  // Exact friction's augmentation r = friction.augmentation / d_N (used only by it).
  const Real augmentation =
      settings_.penalty.d_n > 0 ? settings_.friction.augmentation / settings_.penalty.d_n : 0.0;
  terms_ = make_terms<dim>(settings_, *discretisation_, multipliers_, body_force_, augmentation);
  assembler_ = std::make_unique<Assembler<dim>>(*discretisation_, settings_.law, terms_,
                                                point_temperatures_);
}

template <int dim>
void FormingProblem<dim>::assemble(const VectorX* w, LinearSystem& system,
                                   const FrictionMultipliers<dim>* multipliers) const {
  ScatterPlan::clear(system);
  // The constant-viscosity start has no friction (τ_f(0) = 0), hence no contact state.
  std::vector<ContactPoint<dim>> state;
  if (w && !physics::friction_vanishes(settings_.friction)) state = contact_state(*w, multipliers);
  AssemblyRequest<dim> request;
  request.pass = AssemblyPass::Secant;
  request.velocity = w;
  request.initial_viscosity = settings_.law.secant_viscosity(settings_.initial_rate);
  request.contact = state;
  ScatterSink<dim> sink(mesh_, plan(), constraints().values, &system, nullptr);
  assembler_->run(request, &sink);
}

template <int dim>
PowerTerms FormingProblem<dim>::powers(const VectorX& u,
                                       const std::vector<ContactPoint<dim>>& contact) const {
  AssemblyRequest<dim> request;
  request.pass = AssemblyPass::Power;
  request.velocity = &u;
  request.contact = contact;
  PowerTerms power;
  assembler_->run(request, nullptr, &power);
  // A distributed run's pass covered the rank's own cells (and their Γ3 faces): the
  // integrals add up over the ranks, the same bits on every rank.
  if (const Distribution& distribution = discretisation_->distribution();
      distribution.distributed()) {
    std::array<Real, 5> terms{power.plastic_dissipation, power.viscous_form,
                              power.volumetric_penalty, power.contact_penalty, power.friction};
    distribution.sum_over_ranks(terms);
    power = {terms[0], terms[1], terms[2], terms[3], terms[4]};
  }
  return power;
}

template <int dim>
Real FormingProblem<dim>::driven_force(const LinearSystem& system, const VectorX& u) const {
  const VectorX reactions = system.reaction_rows * u;
  Real force = 0.0;
  for (Index dof : constraints().driven_dofs) {
    const Index row = plan().prescribed_index(dof);
    force += reactions[row] - system.prescribed_loads[row];
  }
  // A distributed run's system holds the rank's own cells: their reactions add up.
  if (const Distribution& distribution = discretisation_->distribution();
      distribution.distributed())
    distribution.sum_over_ranks(std::span<Real>(&force, 1));
  return force;
}

template class FormingProblem<2>;
template class FormingProblem<3>;

} // namespace formflow::assembly
