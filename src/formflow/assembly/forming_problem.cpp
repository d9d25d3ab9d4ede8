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
    : mesh_(mesh), settings_(settings), constraints_(std::move(constraints)),
      body_force_(std::move(body_force)), full_rule_(fem::gauss_rule<dim>(mesh.order + 1)),
      volumetric_rule_(fem::gauss_rule<dim>(settings.volumetric_points)),
      facet_rule_(settings.contact.normals == ContactNormals::Nodes
                      ? fem::nodal_rule<dim - 1>(mesh.order + 1)
                      : fem::gauss_rule<dim - 1>(mesh.order + 1)) {
  FF_ASSERT(dim == 2 || !axisymmetric(), "axisymmetry is a two-dimensional formulation");
  BlockDofs blocks;
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    blocks.add(fem::dofs_of_nodes<dim>(mesh.cells.col(cell)));
  plan_ = std::make_unique<ScatterPlan>(n_dofs(), constraints_.prescribed, blocks);

  // Contact faces, grouped by cell so that the cell loop adds them to the
  // cell's own local matrix (no extra blocks in the pattern).
  std::vector<std::vector<Index>> per_cell(mesh.n_cells());
  for (Index f = 0; f < static_cast<Index>(mesh.facets.size()); ++f)
    if (mesh::is_contact(mesh.facets[f].label)) {
      per_cell[mesh.facets[f].cell].push_back(static_cast<Index>(contact_facets_.size()));
      contact_facets_.push_back(f);
    }
  cell_contact_offsets_.push_back(0);
  for (const auto& list : per_cell) {
    cell_contact_.insert(cell_contact_.end(), list.begin(), list.end());
    cell_contact_offsets_.push_back(static_cast<Index>(cell_contact_.size()));
  }
  if (contact_points_at_nodes())
    contact_normals_ =
        nodal_contact_normals<dim>(mesh, contact_facets_, settings.contact.corner_angle);

  // The mesh never moves: map every cell and Γ3 face once (fem/values_cache.hpp);
  // the loops below run every iteration on this geometry.
  {
    typename fem::CellValues<dim>::Gradients nodes, no_velocity;
    const auto map_cell = [&](Index cell, fem::CellValues<dim>& values) {
      gather(cell, nullptr, nodes, no_velocity);
      reinit(values, nodes);
    };
    full_cache_ = std::make_unique<fem::CellValuesCache<dim>>(
        mesh.n_cells(), fem::CellValues<dim>(mesh.order, full_rule_), map_cell);
    volumetric_cache_ = std::make_unique<fem::CellValuesCache<dim>>(
        mesh.n_cells(), fem::CellValues<dim>(mesh.order, volumetric_rule_), map_cell);
    contact_cache_ = std::make_unique<fem::FacetValuesCache<dim>>(
        static_cast<Index>(contact_facets_.size()), fem::FacetValues<dim>(mesh.order, facet_rule_),
        [&](Index position, fem::FacetValues<dim>& values) {
          gather(mesh.facets[contact_facets_[position]].cell, nullptr, nodes, no_velocity);
          reinit_contact(values, nodes, position);
        });
  }

  // The mollifier works on the fixed geometry of Γ3: build it once.
  const std::vector<ContactPoint<dim>> geometry = contact_state(VectorX::Zero(n_dofs()));
  MatrixX points(dim, static_cast<Index>(geometry.size()));
  std::vector<Real> weights;
  for (std::size_t k = 0; k < geometry.size(); ++k) {
    points.col(static_cast<Index>(k)) = geometry[k].position;
    weights.push_back(geometry[k].weight);
  }
  average_ = std::make_unique<physics::NonlocalAverage>(points, weights, settings.friction.radius);

  fem::FacetValues<dim> facet_values(mesh.order, facet_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  for (const mesh::BoundaryFacet& facet : mesh.facets) {
    if (facet.label != constraints_.driven_label) continue;
    gather(facet.cell, nullptr, coordinates, unused);
    reinit(facet_values, coordinates, facet.local_face);
    for (int q = 0; q < facet_values.n_points(); ++q) driven_height_ += facet_values.JxW(q);
  }
}

template <int dim>
void FormingProblem<dim>::gather(Index cell, const VectorX* u,
                                 typename fem::CellValues<dim>::Gradients& coordinates,
                                 typename fem::CellValues<dim>::Gradients& velocities) const {
  const int n = mesh_.nodes_per_cell();
  coordinates.resize(dim, n);
  velocities.setZero(dim, n);
  for (int a = 0; a < n; ++a) {
    const Index node = mesh_.cells(a, cell);
    coordinates.col(a) = mesh_.nodes.col(node);
    if (u) velocities.col(a) = u->template segment<dim>(fem::dof_of<dim>(node, 0));
  }
}

template <int dim>
void FormingProblem<dim>::reinit_contact(
    fem::FacetValues<dim>& values, const typename fem::CellValues<dim>::Gradients& coordinates,
    Index position) const {
  if (contact_cache_) return contact_cache_->load(position, values);
  reinit(values, coordinates, mesh_.facets[contact_facets_[position]].local_face);
  if (contact_normals_.empty()) return;
  // Penalty, σ_N, u_T and the friction projector all read these normals: the
  // power balance needs one normal per point throughout.
  for (int q = 0; q < values.n_points(); ++q)
    values.set_normal(q, contact_normals_[position * values.n_points() + q]);
}

template <int dim>
std::vector<ContactPoint<dim>>
FormingProblem<dim>::contact_state(const VectorX& u,
                                   const FrictionMultipliers<dim>* multipliers) const {
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  std::vector<ContactPoint<dim>> state;
  state.reserve(contact_facets_.size() * facet_rule_.size());
  // The Tresca and hybrid thresholds read the flow stress at the surface point, taken
  // at max(ε̄̇, rate1): below rate1 the law's linear continuation would make a rigid
  // billet frictionless.
  const bool shear_yield = average_ && physics::needs_shear_yield(settings_.friction);
  for (Index position = 0; position < static_cast<Index>(contact_facets_.size()); ++position) {
    const Index f = contact_facets_[position];
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
  if (!average_) return state; // during construction: geometry only

  std::vector<Real> pressure(state.size()), mean;
  for (std::size_t k = 0; k < state.size(); ++k) pressure[k] = state[k].contact_pressure;
  average_->apply(pressure, mean);
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

  fem::CellValues<dim> full_values(mesh_.order, full_rule_);
  fem::CellValues<dim> volumetric_values(mesh_.order, volumetric_rule_);
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  const int n_local = mesh_.nodes_per_cell() * dim;
  MatrixX local_matrix(n_local, n_local);
  VectorX local_load(n_local);
  std::vector<Real> viscosity(full_rule_.size());
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
    plan_->scatter(cell, local_matrix, constraints_.values, system);
    if (multipliers_ && multipliers_->has_cell_loads()) scatter_load(cell, local_load, system);
    if (with_friction && has_exact_friction())
      add_friction_loads(cell, state, coordinates, facet_values, system);
    if (body_force_) {
      add_body_force(full_values, local_load);
      plan_->scatter_load(cell, local_load, system);
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
  const int n_q = facet_rule_.size();
  for (Index k = cell_contact_offsets_[cell]; k < cell_contact_offsets_[cell + 1]; ++k) {
    const Index position = cell_contact_[k];
    reinit_contact(facet_values, coordinates, position);
    for (int q = 0; q < n_q; ++q) {
      const ContactPoint<dim>& point = state[position * n_q + q];
      if (point.friction_load.isZero(0.0)) continue;
      for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
        for (int i = 0; i < dim; ++i) {
          const Real load = point.friction_load[i] * facet_values.shape(q)[a] * facet_values.JxW(q);
          const Index dof = fem::dof_of<dim>(mesh_.cells(a, cell), i);
          if (const Index row = plan_->free_index(dof); row >= 0)
            system.rhs[row] -= load;
          else
            system.prescribed_loads[plan_->prescribed_index(dof)] -= load;
        }
    }
  }
}

template <int dim>
void FormingProblem<dim>::assemble_contact(
    Index cell, const std::vector<ContactPoint<dim>>* state,
    const typename fem::CellValues<dim>::Gradients& coordinates,
    fem::FacetValues<dim>& facet_values, MatrixX& local_matrix, VectorX& local_load) const {
  const int n_q = facet_rule_.size();
  std::vector<Real> weight(n_q, 0.0);
  for (Index k = cell_contact_offsets_[cell]; k < cell_contact_offsets_[cell + 1]; ++k) {
    const Index position = cell_contact_[k];
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
      if (const Index free = plan_->free_index(dof); free >= 0)
        system.rhs[free] += load;
      else
        system.prescribed_loads[plan_->prescribed_index(dof)] += load;
    }
}

namespace {

/// ε̇ at point q of cell or face `values` for the cell's nodal `velocities`; in
/// axisymmetry with the hoop rate u_r/r in the θθ (third) slot.
template <int dim, class Values>
Tensor3 strain_rate_of(const Values& values,
                       const typename fem::CellValues<dim>::Gradients& velocities, int q,
                       bool axisymmetric) {
  Tensor2<dim> gradient;
  with_node_count<dim>(values.n_nodes(), [&](auto n_nodes) { // fixed sizes: runs at every point
    using NodeValues = Eigen::Matrix<Real, dim, decltype(n_nodes)::value>;
    gradient = physics::velocity_gradient<dim>(
        Eigen::Map<const NodeValues>(velocities.data(), dim, values.n_nodes()),
        Eigen::Map<const NodeValues>(values.gradients(q).data(), dim, values.n_nodes()));
  });
  Tensor3 rate = physics::strain_rate<dim>(gradient);
  if constexpr (dim == 2)
    if (axisymmetric)
      physics::add_hoop_rate<dim>(rate, gradient, (velocities * values.shape(q))[1],
                                  values.point(q)[1]);
  return rate;
}

} // namespace

template <int dim>
Tensor3
FormingProblem<dim>::strain_rate_at(const fem::CellValues<dim>& values,
                                    const typename fem::CellValues<dim>::Gradients& velocities,
                                    int q) const {
  return strain_rate_of<dim>(values, velocities, q, axisymmetric());
}

template <int dim>
Tensor3
FormingProblem<dim>::strain_rate_at(const fem::FacetValues<dim>& values,
                                    const typename fem::CellValues<dim>::Gradients& velocities,
                                    int q) const {
  return strain_rate_of<dim>(values, velocities, q, axisymmetric());
}

template <int dim>
Real FormingProblem<dim>::hoop_rate_at(const fem::CellValues<dim>& values,
                                       const typename fem::CellValues<dim>::Gradients& velocities,
                                       int q) const {
  if (!axisymmetric()) return 0.0;
  return strain_rate_at(values, velocities, q)(2, 2);
}

template <int dim>
Real FormingProblem<dim>::driven_force(const LinearSystem& system, const VectorX& u) const {
  const VectorX reactions = system.reaction_rows * u;
  Real force = 0.0;
  for (Index dof : constraints_.driven_dofs) {
    const Index row = plan_->prescribed_index(dof);
    force += reactions[row] - system.prescribed_loads[row];
  }
  return force;
}

template class FormingProblem<2>;
template class FormingProblem<3>;

} // namespace formflow::assembly
