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
#include "formflow/core/parallel_tasks.hpp"

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
  // A distributed run (issue 20): the tangent and the coupling stay this rank's shares
  // (its own cells); the force is ghosted like the velocity: every dof the rank holds
  // gets the sum of the ranks' shares (the line search's slopes and the stop rule are
  // inner products over the owners, the reaction a sum over them: driven_force).
  discretisation_->owned_dofs().sum_shares(internal_force);
}

template <int dim>
void FormingProblem<dim>::apply_coupling(const UnsymmetricTangent<dim>& coupling,
                                         const VectorX& x_free, VectorX& y_free) const {
  const int n_local = coupling.n_local, n_nodes = mesh_.nodes_per_cell();
  // The points [first, last): each adds to the rows of its own cell's dofs.
  const auto apply_points = [&](std::size_t first, std::size_t last) {
    std::vector<Index> rows(n_local);
    CellVector x_local(n_local);
    Index last_cell = -1;
    for (std::size_t k = first; k < last; ++k) {
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
  };
  // By the assembly's phases, each phase's blocks at the same time (they share no dof:
  // every entry of y gets its points' terms in the same order as in one sweep).
  const bool by_blocks = !coupling.phase_starts.empty() &&
                         coupling.phase_starts.back().back() == coupling.cells.size() &&
                         !discretisation_->owned_dofs().distributed();
  if (by_blocks) {
    const std::size_t threads = compute_threads();
    for (const std::vector<std::size_t>& starts : coupling.phase_starts)
      run_tasks(starts.size() - 1, threads,
                [&](std::size_t block) { apply_points(starts[block], starts[block + 1]); });
  } else {
    apply_points(0, coupling.cells.size());
  }
  if (!coupling.has_friction) return;

  // dσ̄_N[x] is the mollified u_N(x)/d_N: contact_state of x itself (it is linear in x).
  const std::vector<ContactPoint<dim>> change =
      contact_state(plan().expand(x_free, VectorX::Zero(n_dofs())));
  fem::FacetValues<dim> facet_values(mesh_.cell_type(), facet_rule());
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  const int n_face_q = facet_rule().size();
  for (std::size_t position = 0; position < discretisation_->contact_facets().size(); ++position) {
    const mesh::BoundaryFacet& facet = mesh_.facets[discretisation_->contact_facets()[position]];
    // A distributed run's share: the faces of its own cells (the cell part above is too).
    if (!discretisation_->assembles(facet.cell)) continue;
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

template <int dim>
void FormingProblem<dim>::apply_coupling_transpose(const UnsymmetricTangent<dim>& coupling,
                                                   const VectorX& x, VectorX& y) const {
  // N = Σ_points c (divergence row)ᵀ (deviator row), so Nᵀ x = Σ c (deviator)ᵀ (divergence · x).
  const int n_local = coupling.n_local, n_nodes = mesh_.nodes_per_cell();
  std::vector<Index> dofs(n_local);
  Index last_cell = -1;
  for (std::size_t k = 0; k < coupling.cells.size(); ++k) {
    const Index cell = coupling.cells[k];
    if (cell != last_cell) {
      for (int a = 0; a < n_nodes; ++a)
        for (int i = 0; i < dim; ++i) dofs[a * dim + i] = fem::dof_of<dim>(mesh_.cells(a, cell), i);
      last_cell = cell;
    }
    const Real* divergence = coupling.rows.data() + 2 * k * n_local;
    const Real* deviator = divergence + n_local;
    Real g = 0.0;
    for (int l = 0; l < n_local; ++l) g += divergence[l] * x[dofs[l]];
    g *= coupling.coefficients[k];
    for (int l = 0; l < n_local; ++l) y[dofs[l]] += g * deviator[l];
  }
  if (!coupling.has_friction) return;

  // The friction part is N_f = B S M: M x = σ̄_N(x) = A (u_N(x)/d_N) at the Γ3 points
  // (A the mollifier, the normals fixed), S the per-point (∂τ_f/∂σ̄_N) ĝ, B the
  // tractions' nodal forces ∫ φ_a · dΓ. So N_fᵀ x = Mᵀ Sᵀ Bᵀ x, in two face loops.
  FF_ASSERT(multipliers_ == nullptr, "the friction coupling's transpose is the penalty contact's");
  // A distributed run: each rank its own cells' faces (x ghosted, y a share); the
  // points' weighted traces are summed over the ranks before the mollifier's transpose,
  // which reaches every point.
  const Distribution& distribution = discretisation_->distribution();
  fem::FacetValues<dim> facet_values(mesh_.cell_type(), facet_rule());
  typename fem::CellValues<dim>::Gradients coordinates, unused;
  const int n_face_q = facet_rule().size();
  const std::size_t n_facets = discretisation_->contact_facets().size();
  std::vector<Real> weighted(n_facets * n_face_q, 0.0), spread;
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t position = 0; position < n_facets; ++position) {
      const mesh::BoundaryFacet& facet = mesh_.facets[discretisation_->contact_facets()[position]];
      if (!discretisation_->assembles(facet.cell)) continue; // another rank's face
      gather(facet.cell, nullptr, coordinates, unused);
      reinit_contact(facet_values, coordinates, static_cast<Index>(position));
      for (int q = 0; q < n_face_q; ++q) {
        const std::size_t k = position * n_face_q + q;
        if (pass == 0) { // Sᵀ Bᵀ x: the slip-weighted trace of x at each point
          if (coupling.threshold_slip[k].isZero(0.0)) continue;
          Point<dim> trace = Point<dim>::Zero();
          for (int a = 0; a < n_nodes; ++a)
            trace += facet_values.shape(q)[a] *
                     x.template segment<dim>(fem::dof_of<dim>(mesh_.cells(a, facet.cell), 0));
          weighted[k] = facet_values.JxW(q) * coupling.threshold_slip[k].dot(trace);
        } else { // Mᵀ: u_N = φ_a n · u_a, divided by d_N
          const Point<dim> load =
              (spread[k] / settings_.penalty.d_n) * Point<dim>(facet_values.normal(q));
          for (int a = 0; a < n_nodes; ++a)
            y.template segment<dim>(fem::dof_of<dim>(mesh_.cells(a, facet.cell), 0)) +=
                facet_values.shape(q)[a] * load;
        }
      }
    }
    if (pass == 0) {
      if (distribution.distributed()) distribution.sum_over_ranks(weighted);
      discretisation_->mollifier().apply_transpose(weighted, spread);
    }
  }
}

namespace {

/// Receives the per-cell internal forces and keeps w_K · f_K for each cell.
template <int dim> class WeightedForceSink final : public AssemblySink {
public:
  WeightedForceSink(const mesh::Mesh<dim>& mesh, const VectorX& weight, VectorX& per_cell)
      : mesh_(mesh), weight_(weight), per_cell_(per_cell) {}
  void add_matrix(Index, const MatrixX&) override {}
  void add_load(Index, const VectorX&) override {}
  void add_force(Index cell, const CellVector& local) override {
    Real sum = 0.0;
    for (int a = 0; a < mesh_.nodes_per_cell(); ++a)
      sum += weight_.template segment<dim>(fem::dof_of<dim>(mesh_.cells(a, cell), 0))
                 .dot(local.template segment<dim>(a * dim));
    per_cell_[cell] += sum;
  }
  bool concurrent() const override { return true; } // each cell its own entry

private:
  const mesh::Mesh<dim>& mesh_;
  const VectorX& weight_;
  VectorX& per_cell_;
};

} // namespace

template <int dim>
VectorX FormingProblem<dim>::weighted_cell_forces(const VectorX& u,
                                                  std::span<const Real> thresholds,
                                                  const VectorX& weight) const {
  FF_ASSERT(terms_.newton_ready() && !body_force_,
            "the internal force of Newton's penalty problem (or the condensed mixed one)");
  std::vector<ContactPoint<dim>> state = contact_state(u);
  const NewtonDuals<dim> primal;
  NewtonPass<dim> pass{state, thresholds, std::span<const Point<dim>>(), nullptr};
  for (const auto& term : terms_.face) term->begin_newton(pass);
  AssemblyRequest<dim> request;
  request.pass = AssemblyPass::Force;
  request.velocity = &u;
  if (!physics::friction_vanishes(settings_.friction)) request.contact = state;
  request.duals = &primal;
  request.every_cell = true; // each cell's own value, on every rank
  VectorX per_cell = VectorX::Zero(mesh_.n_cells());
  WeightedForceSink<dim> sink(mesh_, weight, per_cell);
  assembler_->run(request, &sink);
  return per_cell;
}

template <int dim> Real FormingProblem<dim>::driven_force(const VectorX& internal_force) const {
  // A distributed run's force is ghosted: each driven dof counted on its owner.
  const OwnedDofs& owned = discretisation_->owned_dofs();
  Real force = 0.0;
  for (Index dof : constraints().driven_dofs)
    if (owned.owns(dof)) force += internal_force[dof];
  if (owned.distributed())
    discretisation_->distribution().sum_over_ranks(std::span<Real>(&force, 1));
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
template void FormingProblem<2>::apply_coupling_transpose(const UnsymmetricTangent<2>&,
                                                          const VectorX&, VectorX&) const;
template void FormingProblem<3>::apply_coupling_transpose(const UnsymmetricTangent<3>&,
                                                          const VectorX&, VectorX&) const;
template VectorX FormingProblem<2>::weighted_cell_forces(const VectorX&, std::span<const Real>,
                                                         const VectorX&) const;
template VectorX FormingProblem<3>::weighted_cell_forces(const VectorX&, std::span<const Real>,
                                                         const VectorX&) const;
template Real FormingProblem<2>::driven_force(const VectorX&) const;
template Real FormingProblem<3>::driven_force(const VectorX&) const;

} // namespace formflow::assembly
