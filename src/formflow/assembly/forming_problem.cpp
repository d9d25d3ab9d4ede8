// SPDX-License-Identifier: MIT
// Cell and contact-face loops of the secant system K(w) u = F.
#include "formflow/assembly/forming_problem.hpp"

#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/physics/kinematics.hpp"

namespace formflow::assembly {

namespace {

bool friction_acts_on(const physics::Friction& friction, mesh::BoundaryLabel label) {
  if (friction.mu <= 0) return false;
  return (label == mesh::BoundaryLabel::Container && friction.on_container) ||
         (label == mesh::BoundaryLabel::Die && friction.on_die);
}

}  // namespace

template <int dim>
FormingProblem<dim>::FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings)
    : FormingProblem(mesh, settings, make_process_constraints(mesh, settings.process), {}) {}

template <int dim>
FormingProblem<dim>::FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings,
                                    DirichletConstraints constraints, BodyForce<dim> body_force)
    : mesh_(mesh),
      settings_(settings),
      constraints_(std::move(constraints)),
      body_force_(std::move(body_force)),
      full_rule_(fem::gauss_rule<dim>(mesh.order + 1)),
      volumetric_rule_(fem::gauss_rule<dim>(settings.volumetric_points)),
      facet_rule_(fem::gauss_rule<dim - 1>(mesh.order + 1)) {
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
    facet_values.reinit(coordinates, facet.local_face);
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
std::vector<ContactPoint<dim>> FormingProblem<dim>::contact_state(const VectorX& u) const {
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  std::vector<ContactPoint<dim>> state;
  state.reserve(contact_facets_.size() * facet_rule_.size());
  for (Index f : contact_facets_) {
    const mesh::BoundaryFacet& facet = mesh_.facets[f];
    gather(facet.cell, &u, coordinates, velocities);
    facet_values.reinit(coordinates, facet.local_face);
    for (int q = 0; q < facet_values.n_points(); ++q) {
      ContactPoint<dim> point;
      point.facet = f;
      point.position = facet_values.point(q);
      point.normal = facet_values.normal(q);
      point.weight = facet_values.JxW(q);
      const Point<dim> velocity = velocities * facet_values.shape(q);
      point.normal_velocity = velocity.dot(point.normal);
      point.tangential_velocity = velocity - point.normal_velocity * point.normal;
      point.contact_pressure = point.normal_velocity / settings_.penalty.d_n;  // −σ_N (eq. 3.6)
      state.push_back(point);
    }
  }
  if (!average_) return state;  // during construction: geometry only

  std::vector<Real> pressure(state.size()), mean;
  for (std::size_t k = 0; k < state.size(); ++k) pressure[k] = state[k].contact_pressure;
  average_->apply(pressure, mean);
  for (std::size_t k = 0; k < state.size(); ++k) {
    ContactPoint<dim>& point = state[k];
    point.mean_contact_pressure = mean[k];
    if (!friction_acts_on(settings_.friction, mesh_.facets[point.facet].label)) continue;
    point.friction_threshold = physics::friction_threshold(settings_.friction.mu, mean[k]);
    point.friction_weight = physics::friction_weight(
        point.friction_threshold, point.tangential_velocity.norm(), settings_.friction.d_t);
  }
  return state;
}

template <int dim>
void FormingProblem<dim>::assemble(const VectorX* w, LinearSystem& system) const {
  ScatterPlan::clear(system);
  const bool with_friction = w && settings_.friction.mu > 0;
  std::vector<ContactPoint<dim>> state;
  if (with_friction) state = contact_state(*w);

  fem::CellValues<dim> full_values(mesh_.order, full_rule_);
  fem::CellValues<dim> volumetric_values(mesh_.order, volumetric_rule_);
  fem::FacetValues<dim> facet_values(mesh_.order, facet_rule_);
  typename fem::CellValues<dim>::Gradients coordinates, velocities;
  const int n_local = mesh_.nodes_per_cell() * dim;
  MatrixX local_matrix(n_local, n_local);
  VectorX local_load;
  std::vector<Real> viscosity(full_rule_.size());
  const Real initial_viscosity = settings_.law.secant_viscosity(settings_.initial_rate);

  for (Index cell = 0; cell < mesh_.n_cells(); ++cell) {
    gather(cell, w, coordinates, velocities);
    full_values.reinit(coordinates);
    volumetric_values.reinit(coordinates);
    for (int q = 0; q < full_values.n_points(); ++q) {
      if (!w) {
        viscosity[q] = initial_viscosity;
        continue;
      }
      const Tensor3 rate = physics::strain_rate<dim>(
          physics::velocity_gradient<dim>(velocities, full_values.gradients(q)));
      viscosity[q] = settings_.law.secant_viscosity(physics::equivalent_strain_rate(rate));
    }
    local_matrix.setZero();
    add_viscous_term<dim>(full_values, viscosity, settings_.viscous_strain, local_matrix);
    add_volumetric_penalty<dim>(volumetric_values, settings_.penalty.d, local_matrix);
    assemble_contact(cell, with_friction ? &state : nullptr, coordinates, facet_values, local_matrix);
    plan_->scatter(cell, local_matrix, constraints_.values, system);
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
    for (int a = 0; a < values.n_nodes(); ++a)  // ∫ f·φ_a e_i dx
      local_load.template segment<dim>(a * dim) += values.shape(q)[a] * values.JxW(q) * force;
  }
}

template <int dim>
void FormingProblem<dim>::assemble_contact(Index cell, const std::vector<ContactPoint<dim>>* state,
                                           const typename fem::CellValues<dim>::Gradients& coordinates,
                                           fem::FacetValues<dim>& facet_values,
                                           MatrixX& local_matrix) const {
  const int n_q = facet_rule_.size();
  std::vector<Real> weight(n_q, 0.0);
  for (Index k = cell_contact_offsets_[cell]; k < cell_contact_offsets_[cell + 1]; ++k) {
    const Index position = cell_contact_[k];
    facet_values.reinit(coordinates, mesh_.facets[contact_facets_[position]].local_face);
    add_contact_penalty<dim>(facet_values, settings_.penalty.d_n, local_matrix);
    if (!state) continue;
    for (int q = 0; q < n_q; ++q) weight[q] = (*state)[position * n_q + q].friction_weight;
    add_friction_term<dim>(facet_values, weight, local_matrix);
  }
}

template <int dim>
Real FormingProblem<dim>::driven_force(const LinearSystem& system, const VectorX& u) const {
  const VectorX reactions = system.reaction_rows * u;
  Real force = 0.0;
  for (Index dof : constraints_.driven_dofs) force += reactions[plan_->prescribed_index(dof)];
  return force;
}

template class FormingProblem<2>;
template class FormingProblem<3>;

}  // namespace formflow::assembly
