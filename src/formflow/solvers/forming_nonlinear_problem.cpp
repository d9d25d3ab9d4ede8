// SPDX-License-Identifier: MIT
// The forming problem's Newton pieces and Uzawa updates behind the drivers' interface.
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/newton_duals.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <map>
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
  if (!tangent) return;
  // A distributed run: a rank whose own cells hold no coupling (a rigid part) still joins
  // the others' GMRES, whose every product is collective.
  Real coupled = coupling_.empty() ? 0.0 : 1.0;
  if (const assembly::Distribution& distribution = problem_.discretisation().distribution();
      distribution.distributed())
    distribution.sum_over_ranks(std::span<Real>(&coupled, 1));
  coupled_ = coupled > 0;
}

template <int dim> void FormingNonlinearProblem<dim>::add_up_shares(VectorX& values) const {
  problem_.discretisation().owned_dofs().sum_shares(values);
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
  const assembly::Discretisation<dim>& discretisation = problem_.discretisation();
  return multipliers.update(velocity, normal_velocity, discretisation.cell_ranks(),
                            discretisation.distribution());
}

template <int dim> void FormingNonlinearProblem<dim>::enable_exact_stick() {
  FF_ASSERT(problem_.has_exact_friction() && problem_.discretisation().contact_points_at_nodes(),
            "exact stick needs exact friction on nodal contact points (checked with the case)");
  stick_nodes_ = exact_stick_nodes();
  constrained_.clear();
}

template <int dim>
std::vector<typename FormingNonlinearProblem<dim>::StickNode>
FormingNonlinearProblem<dim>::exact_stick_nodes() const {
  const mesh::Mesh<dim>& mesh = problem_.mesh();
  const auto& facets = problem_.discretisation().contact_facets();
  const int n_q = problem_.discretisation().facet_rule().size();
  // The nodal rule's points are the face nodes in face-node order (contact_normals.cpp).
  const auto state = problem_.contact_state(problem_.constraints().values);
  std::map<Index, std::vector<std::size_t>> points_at;
  for (std::size_t p = 0; p < facets.size(); ++p) {
    const mesh::BoundaryFacet& facet = mesh.facets[facets[p]];
    const std::vector<int> face_nodes = mesh.face_nodes(facet.local_face);
    FF_ASSERT(static_cast<int>(face_nodes.size()) == n_q, "one nodal-rule point per face node");
    for (int q = 0; q < n_q; ++q)
      points_at[mesh.cells(face_nodes[q], facet.cell)].push_back(p * n_q + q);
  }
  std::vector<StickNode> nodes;
  for (const auto& [node, points] : points_at) {
    StickNode entry{node, points, {}, 0.0};
    for (std::size_t k : points) entry.weight += state[k].weight;
    // A prescribed dof (a symmetry face in 3D) leaves the tangents along the free ones.
    bool eligible = false;
    for (int i = 0; i < dim; ++i) {
      entry.rows[i] = problem_.plan().free_index(fem::dof_of<dim>(node, i));
      eligible = eligible || entry.rows[i] >= 0;
    }
    for (std::size_t k : points)
      eligible = eligible && state[k].normal.dot(state[points.front()].normal) > 1.0 - 1e-12;
    if (eligible) nodes.push_back(std::move(entry));
  }
  return nodes;
}

template <int dim>
std::vector<StepConstraint> FormingNonlinearProblem<dim>::step_constraints(const VectorX& u) const {
  constrained_.clear();
  held_points_.clear();
  if (stick_nodes_.empty() || !friction_) return {};
  const auto state = problem_.contact_state(u, friction_);
  std::vector<StepConstraint> constraints;
  for (std::size_t n = 0; n < stick_nodes_.size(); ++n) {
    const StickNode& node = stick_nodes_[n];
    // Its points share velocity, normal and τ_f, so they stick together.
    bool stuck = true;
    for (std::size_t k : node.points) stuck = stuck && state[k].sticking;
    if (!stuck) continue;
    const Point<dim> normal = state[node.points.front()].normal;
    const Point<dim> slip = state[node.points.front()].tangential_velocity;
    // Orthonormal tangents of the node's plane (2D: one; 3D: two).
    std::vector<Point<dim>> tangents;
    if constexpr (dim == 2) {
      tangents.push_back(Point<dim>(-normal[1], normal[0]));
    } else {
      const Point<dim> seed = std::abs(normal[0]) < 0.9 ? Point<dim>::UnitX() : Point<dim>::UnitY();
      const Point<dim> first = (seed - seed.dot(normal) * normal).normalized();
      tangents.push_back(first);
      tangents.push_back(normal.cross(first));
    }
    for (const auto& [direction, target] : free_tangents(node, normal, tangents, slip)) {
      StepConstraint c;
      for (int i = 0; i < dim; ++i) {
        if (node.rows[i] < 0) continue;
        c.rows.push_back(node.rows[i]);
        c.coefficients.push_back(direction[i]);
      }
      c.target = target; // (u + δ)·e = 0
      constraints.push_back(std::move(c));
      constrained_.emplace_back(n, direction);
    }
  }
  return constraints;
}

template <int dim>
std::vector<std::pair<Point<dim>, Real>>
FormingNonlinearProblem<dim>::free_tangents(const StickNode& node, const Point<dim>& normal,
                                            const std::vector<Point<dim>>& tangents,
                                            const Point<dim>& slip) {
  // The step moves the free dofs only: tangent t is held by (Π_F t)·δ = −u·t. Gram–Schmidt
  // keeps the node's constraints orthonormal (what the condensation needs); a direction
  // with no free part (the slip along it is prescribed) is dropped, and so is one that
  // leaves the tangent plane (a prescribed dof oblique to the normal: the reaction along
  // it would not be a friction traction; the stick penalty holds it as before).
  constexpr Real tiny = 1e-8;
  std::vector<std::pair<Point<dim>, Real>> kept;
  for (const Point<dim>& tangent : tangents) {
    Point<dim> direction = tangent;
    for (int i = 0; i < dim; ++i)
      if (node.rows[i] < 0) direction[i] = 0.0;
    Real target = -slip.dot(tangent);
    for (const auto& [previous, previous_target] : kept) {
      const Real along = direction.dot(previous);
      direction -= along * previous;
      target -= along * previous_target;
    }
    const Real length = direction.norm();
    if (length < tiny || std::abs(direction.dot(normal)) > tiny * length) continue;
    kept.emplace_back(direction / length, target / length);
  }
  return kept;
}

template <int dim>
void FormingNonlinearProblem<dim>::constrained_step_taken(const std::vector<Real>& reactions,
                                                          Real t) {
  FF_ASSERT(reactions.size() == constrained_.size() && friction_, "one reaction per constraint");
  if (friction_->traction.empty())
    friction_->traction.assign(problem_.n_contact_points(), Point<dim>::Zero());
  for (std::size_t k = 0; k < reactions.size(); ++k) {
    const StickNode& node = stick_nodes_[constrained_[k].first];
    // With the nodal rule λ̂ loads its node alone, by W λ̂ (W the node's share of Γ3).
    const Point<dim> change = (-t * reactions[k] / node.weight) * constrained_[k].second;
    for (std::size_t p : node.points) friction_->traction[p] += change;
    // A node with two tangents (3D) is listed once per constraint: its points once.
    if (k == 0 || constrained_[k - 1].first != constrained_[k].first)
      held_points_.insert(held_points_.end(), node.points.begin(), node.points.end());
  }
}

template <int dim>
Real FormingNonlinearProblem<dim>::slip_reversal(const VectorX& u, const VectorX& step) const {
  Real first = std::numeric_limits<Real>::infinity();
  if (stick_nodes_.empty() || !friction_) return first;
  const auto state = problem_.contact_state(u, friction_);
  // u_T is linear in u: the step's own tangential velocity is its change.
  const auto change = problem_.contact_state(step);
  for (const StickNode& node : stick_nodes_) {
    const std::size_t k = node.points.front();
    const Real traction = state[k].friction_traction.norm();
    if (state[k].sticking || state[k].friction_threshold <= 0 || !(traction > 0)) continue;
    const Point<dim> direction = state[k].friction_traction / traction;
    const Real along = state[k].tangential_velocity.dot(direction);
    const Real rate = change[k].tangential_velocity.dot(direction);
    if (along > 0 && rate < 0 && -along / rate <= 1.0) first = std::min(first, -along / rate);
  }
  return first;
}

template class FormingNonlinearProblem<2>;
template class FormingNonlinearProblem<3>;

} // namespace formflow::solvers
