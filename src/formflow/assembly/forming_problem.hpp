// SPDX-License-Identifier: MIT
// The discrete regularised penalty problem (SPEC §2, eq. 3.19) and its secant
// linearisation K(w) u = F (eq. 5.3): assembly of the global system for a given w.
#pragma once

#include "formflow/assembly/assembler.hpp"
#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/constraints.hpp"
#include "formflow/assembly/contact_normals.hpp"
#include "formflow/assembly/discretisation.hpp"
#include "formflow/assembly/friction_multipliers.hpp"
#include "formflow/assembly/problem_settings.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/assembly/terms/term.hpp"
#include "formflow/assembly/terms/term_set.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/values_cache.hpp"
#include "formflow/physics/flow_law.hpp"
#include "formflow/physics/friction.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <span>

namespace formflow::assembly {

template <int dim> class FormingProblem {
public:
  /// The forming process: Dirichlet data from settings.process, no volume load.
  FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings);
  /// Any Dirichlet data and an optional body force (verification problems).
  FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings,
                 DirichletConstraints constraints, BodyForce<dim> body_force);
  /// The terms and the assembler refer to the settings and the discretisation held here.
  FormingProblem(const FormingProblem&) = delete;
  FormingProblem& operator=(const FormingProblem&) = delete;

  /// Assembles K(w) and F into `system`. Without `w` the viscosity is the
  /// constant σ_p(initial_rate)/initial_rate and there is no friction (τ_f(0) = 0).
  /// With exact friction the `multipliers` λ_T enter as the load s·λ_T and the
  /// penalty s·r, s = proj factor at w (null: λ_T = 0); ignored when regularised.
  void assemble(const VectorX* w, LinearSystem& system,
                const FrictionMultipliers<dim>* multipliers = nullptr) const;

  /// Newton (assembly/newton_system.cpp): τ_f(w) at each Γ3 quadrature point,
  /// in contact_state() order (the thresholds assemble_newton takes).
  std::vector<Real> friction_thresholds(const VectorX& w) const;

  /// Newton (assembly/newton_system.cpp), one cell loop at `u` (full dof vector
  /// with the prescribed values) with τ_f frozen at `thresholds`: the internal
  /// force f(u) = K(u) u on every dof (free rows: the residual R(u) of eq. 3.19;
  /// prescribed rows: the reactions); when `tangent` is given, the symmetric part
  /// of the Jacobian built with `duals` (the pattern of the secant system; its rhs
  /// is not meaningful), and when `coupling` is given, the unsymmetric rest (the
  /// full-ε̇ term and dτ_f; empty for the deviatoric form without friction).
  /// Without `tangent` no matrix is built: a residual costs one pass over the
  /// quadrature points (the line search). The exact residual has thresholds = τ_f(u).
  /// A distributed run assembles its own cells: `tangent` and `coupling` are its shares,
  /// the internal force is summed over the ranks (whole, the same on every rank).
  /// Exact friction: the traction proj(λ̂ + r u_T) with `friction_multipliers` λ̂
  /// frozen (null: 0); its semismooth derivative at fixed τ_f goes into `tangent`
  /// (r P at stick, s r (P − t̂ t̂ᵀ) at slip), its τ_f derivative t̂ dτ_f into `coupling`.
  void assemble_newton(const VectorX& u, std::span<const Real> thresholds,
                       const NewtonDuals<dim>& duals, VectorX& internal_force,
                       LinearSystem* tangent = nullptr, UnsymmetricTangent<dim>* coupling = nullptr,
                       const FrictionMultipliers<dim>* friction_multipliers = nullptr) const;

  /// y_f += N x_f for the coupling N of assemble_newton (free dof vectors). A distributed
  /// run's coupling is its own cells' share, and so is the product (the ranks' add up).
  void apply_coupling(const UnsymmetricTangent<dim>& coupling, const VectorX& x_free,
                      VectorX& y_free) const;

  /// y += Nᵀ x for the coupling N of assemble_newton (full dof vectors, prescribed
  /// entries included: the adjoint of a reaction needs the driven rows). The
  /// friction part (dτ_f through the mollified σ̄_N = A u_N/d_N) is transposed as
  /// the penalty contact pressure's: not with attached constraint multipliers
  /// (their σ_N is not u_N/d_N), which callers check (`multipliers()`).
  void apply_coupling_transpose(const UnsymmetricTangent<dim>& coupling, const VectorX& x,
                                VectorX& y) const;

  /// Per cell, w_K · f_K(u): the internal force of assemble_newton (τ_f frozen at
  /// `thresholds`, the exact residual for thresholds = τ_f(u)) cell by cell, with its
  /// Γ3 faces, dotted with the full dof vector `weight`. The entries sum to w · f(u).
  VectorX weighted_cell_forces(const VectorX& u, std::span<const Real> thresholds,
                               const VectorX& weight) const;

  /// Γ3 quadrature-point state for the velocity `u` (full dof vector); with exact
  /// friction the traction is proj(λ_T + r u_T) for the given (or zero) multipliers.
  std::vector<ContactPoint<dim>>
  contact_state(const VectorX& u, const FrictionMultipliers<dim>* multipliers = nullptr) const;

  /// The power of every term at `u` for its Γ3 state `contact` (contact_state(u, …)).
  PowerTerms powers(const VectorX& u, const std::vector<ContactPoint<dim>>& contact) const;
  /// σ_H of every cell at `u`: its integral over the cell and its nodal values, from
  /// the term that carries the pressure (the penalty's ε̇_V/d or the pressure space).
  std::vector<CellPressure> cell_pressures(const VectorX& u) const {
    return assembler_->pressures(u);
  }
  /// Hot forming: the temperature at every full-rule point (cell-major, n_cells × points),
  /// at which every later pass takes the flow law; empty: the isothermal law.
  void set_point_temperatures(std::vector<Real> temperatures) {
    point_temperatures_ = std::move(temperatures);
  }
  const std::vector<Real>& point_temperatures() const { return point_temperatures_; }
  /// Hot forming: the temperature at every Γ3 point (contact_state() order), at which the
  /// Tresca and hybrid thresholds take the shear yield k = σ_p/√3; empty: the isothermal law.
  void set_contact_temperatures(std::vector<Real> temperatures) {
    contact_temperatures_ = std::move(temperatures);
  }
  /// σ_p ε̄̇ at every full-rule point at `u` (cell-major; Assembler::dissipation_density).
  std::vector<Real> dissipation_density(const VectorX& u) const {
    return assembler_->dissipation_density(u);
  }
  /// The problem's weak-form terms (terms/term_set.cpp).
  const TermSet<dim>& terms() const { return terms_; }

  /// Augmentation r of exact friction, friction.augmentation / d_N (stress·time/length).
  Real augmentation() const { return settings_.friction.augmentation / settings_.penalty.d_n; }
  bool has_exact_friction() const {
    return settings_.friction.regularization == physics::FrictionRegularization::None;
  }

  /// Process force: the summed reaction K_c· u − F_c on the driven dofs.
  Real driven_force(const LinearSystem& system, const VectorX& u) const;
  /// The same from the internal force f(u) of assemble_newton (no loads there).
  Real driven_force(const VectorX& internal_force) const;
  /// Mixed formulation and exact constraints (issue 5): the pressure term and
  /// the contact term come from `multipliers` (not owned; may be null = the
  /// penalty terms of eq. 3.8). Assembly records each cell's augmentation in it.
  void attach_multipliers(ConstraintMultipliers<dim>* multipliers) {
    multipliers_ = multipliers;
    choose_terms();
  }
  ConstraintMultipliers<dim>* multipliers() const { return multipliers_; }
  /// The fixed part of the problem: mesh, pattern, rules, caches, Γ3, kinematics.
  const Discretisation<dim>& discretisation() const { return *discretisation_; }
  using Gradients = typename fem::CellValues<dim>::Gradients;

  // Shorthands of discretisation(), for the drivers and cell loops.
  Index n_contact_points() const { return discretisation_->n_contact_points(); }
  Real driven_height() const { return discretisation_->driven_height(); }
  const mesh::Mesh<dim>& mesh() const { return mesh_; }
  const ProblemSettings& settings() const { return settings_; }
  const ScatterPlan& plan() const { return discretisation_->plan(); }
  const DirichletConstraints& constraints() const { return discretisation_->constraints(); }
  Index n_dofs() const { return discretisation_->n_dofs(); }
  bool contact_points_at_nodes() const { return discretisation_->contact_points_at_nodes(); }
  const fem::QuadratureRule<dim>& full_rule() const { return discretisation_->full_rule(); }
  const fem::QuadratureRule<dim>& volumetric_rule() const {
    return discretisation_->volumetric_rule();
  }
  const fem::QuadratureRule<dim - 1>& facet_rule() const { return discretisation_->facet_rule(); }
  template <class Values, class... Face>
  void reinit(Values& values, const Gradients& coordinates, Face... local_face) const {
    discretisation_->reinit(values, coordinates, local_face...);
  }
  bool axisymmetric() const { return discretisation_->axisymmetric(); }
  template <class Values>
  Tensor3 strain_rate_at(const Values& values, const Gradients& velocities, int q) const {
    return discretisation_->strain_rate_at(values, velocities, q);
  }
  Real hoop_rate_at(const fem::CellValues<dim>& values, const Gradients& velocities, int q) const {
    return discretisation_->hoop_rate_at(values, velocities, q);
  }
  void load_cell(Index cell, fem::CellValues<dim>& full_values,
                 fem::CellValues<dim>* volumetric_values) const {
    discretisation_->load_cell(cell, full_values, volumetric_values);
  }
  std::size_t geometry_cache_bytes() const { return discretisation_->geometry_cache_bytes(); }
  void gather(Index cell, const VectorX* u, Gradients& coordinates, Gradients& velocities) const {
    discretisation_->gather(cell, u, coordinates, velocities);
  }

private:
  /// Distributed (issue 20): each rank filled its own cells' Γ3 points from its ghosted
  /// velocity; afterwards every rank holds every point's velocity, pressure and shear
  /// yield (collective, a surface's worth of numbers). One rank: nothing to do.
  void exchange_contact_values(std::vector<ContactPoint<dim>>& state) const;
  /// Chooses the terms for the current multipliers (terms/term_set.cpp).
  void choose_terms();
  void reinit_contact(fem::FacetValues<dim>& values, const Gradients& coordinates,
                      Index position) const {
    discretisation_->reinit_contact(values, coordinates, position);
  }

  const mesh::Mesh<dim>& mesh_;
  ProblemSettings settings_;
  BodyForce<dim> body_force_;
  std::unique_ptr<Discretisation<dim>> discretisation_;
  ConstraintMultipliers<dim>* multipliers_ = nullptr;
  TermSet<dim> terms_;
  std::vector<Real> point_temperatures_;   ///< hot forming (before assembler_, which reads it)
  std::vector<Real> contact_temperatures_; ///< hot forming: T at the Γ3 points
  std::unique_ptr<Assembler<dim>> assembler_;
};

} // namespace formflow::assembly
