// SPDX-License-Identifier: MIT
// The discrete regularised penalty problem (SPEC §2, eq. 3.19) and its secant
// linearisation K(w) u = F (eq. 5.3): assembly of the global system for a given w.
#pragma once

#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/constraints.hpp"
#include "formflow/assembly/contact_normals.hpp"
#include "formflow/assembly/discretisation.hpp"
#include "formflow/assembly/friction_multipliers.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/values_cache.hpp"
#include "formflow/physics/flow_law.hpp"
#include "formflow/physics/friction.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <span>

namespace formflow::assembly {

/// Everything the discrete problem depends on besides the mesh.
struct ProblemSettings {
  physics::Process process;
  physics::FlowLaw law;
  physics::ViscousStrain viscous_strain = physics::ViscousStrain::Full;
  physics::Penalty penalty;
  physics::Friction friction;
  int volumetric_points = 2; ///< Gauss points per direction of the (1/d) term
  Real initial_rate = 1.0;   ///< ε̄̇ of the constant viscosity that starts the iteration
  physics::Symmetry symmetry = physics::Symmetry::Plane; ///< axisymmetric: dim = 2 only
  ContactSettings contact; ///< face or nodal contact normals (assembly/contact_normals.hpp)
};

/// State of the contact boundary Γ3 at one face quadrature point for a velocity w.
template <int dim> struct ContactPoint {
  Index facet = 0; ///< index into Mesh::facets
  Point<dim> position = Point<dim>::Zero();
  Point<dim> normal = Point<dim>::Zero();
  Real weight = 0.0;        ///< JxW
  Real normal_velocity = 0; ///< u_N = u·n (> 0: penetration into the die)
  Point<dim> tangential_velocity = Point<dim>::Zero(); ///< u_T
  Real contact_pressure = 0;                           ///< −σ_N = u_N/d_N
  Real mean_contact_pressure = 0;                      ///< σ̄_N, mollified over radius h
  Real friction_threshold = 0; ///< τ_f of friction.law (μ_f max(σ̄_N, 0), m k, …); 0 where off
  Real threshold_pressure_slope = 0; ///< ∂τ_f/∂σ̄_N at the point (Newton's dτ_f coupling)
  Real shear_yield = 0;     ///< k = σ_p(max(ε̄̇, rate1))/√3 (for laws that need it, else 0)
  Real friction_weight = 0; ///< τ_f/√(|u_T|² + d_T²); exact friction: s·r (see below)
  /// Exact friction only: the lagged part s·λ_T of the traction, a load in K u = F.
  Point<dim> friction_load = Point<dim>::Zero();
  /// λ_T = friction_weight·u_T + friction_load: the friction traction resisting the
  /// slip (σ_T = −λ_T). Regularised: τ_f u_T/√(|u_T|² + d_T²); exact: proj(λ + r u_T).
  Point<dim> friction_traction = Point<dim>::Zero();
  /// Regularised: |λ_T| < 0.99 τ_f (|u_T| < 7 d_T); exact: |λ + r u_T| ≤ τ_f. Never
  /// where τ_f = 0.
  bool sticking = false;
};

/// Exact friction at one point for the frozen multiplier λ̂ (its tangential part)
/// and τ_f = point.friction_threshold: friction_traction = proj(λ̂_T + r u_T) = s t,
/// friction_weight = s r, friction_load = s λ̂_T, sticking = |t| ≤ τ_f (τ_f > 0).
template <int dim>
void exact_friction_point(const Point<dim>& multiplier, Real augmentation,
                          ContactPoint<dim>& point);

/// Dual variables of the primal–dual Newton linearisation (assembly/newton_system.cpp):
/// the viscous stress w ≈ ν ė per cell and full-rule point (cell-major) and the slip
/// direction λ ≈ u_T/√(|u_T|² + d_T²) per Γ3 point (contact_state() order). Empty:
/// the primal choice at the current velocity, i.e. the exact tangent.
template <int dim> struct NewtonDuals {
  std::vector<Tensor3> stress;
  std::vector<Point<dim>> slip;
  bool empty() const { return stress.empty(); }
  void clear() { stress.clear(), slip.clear(); }
};

/// The unsymmetric part of the Newton Jacobian (assembly/newton_system.cpp), applied
/// matrix free; the symmetric rest is the assembled tangent.
///  * the paper's full-ε̇ a-form: ∫ c ε̇_V(v) (ė(u):ε̇(δu)) dx, kept per full-rule
///    point where c ≠ 0 as c·JxW, the divergence row ε̇_V(φ) and the row
///    ė(u):ε̇(φ) over the cell's local dofs (a·dim + i);
///  * the nonlocal friction threshold: ∫_Γ3 dτ_f[δu] (u_T/s)·v_T dΓ with
///    dτ_f = μ_f dσ̄_N where σ̄_N > 0, kept per Γ3 point as μ_f u_T/s (0 elsewhere).
template <int dim> struct UnsymmetricTangent {
  int n_local = 0;
  std::vector<Index> cells;               ///< cell of each kept point
  std::vector<Real> coefficients;         ///< c·JxW per kept point
  std::vector<Real> rows;                 ///< per kept point: divergence row, then ė(u) row
  std::vector<Point<dim>> threshold_slip; ///< per Γ3 point (contact_state() order)
  bool has_friction = false;              ///< some threshold_slip ≠ 0
  void clear() {
    cells.clear(), coefficients.clear(), rows.clear(), threshold_slip.clear(), has_friction = false;
  }
  bool empty() const { return cells.empty() && !has_friction; }
};

/// A volume load f(x) per unit volume (manufactured solutions): adds ∫ f·v dx to F.
template <int dim> using BodyForce = std::function<Point<dim>(const Point<dim>&)>;

template <int dim> class FormingProblem {
public:
  /// The forming process: Dirichlet data from settings.process, no volume load.
  FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings);
  /// Any Dirichlet data and an optional body force (verification problems).
  FormingProblem(const mesh::Mesh<dim>& mesh, const ProblemSettings& settings,
                 DirichletConstraints constraints, BodyForce<dim> body_force);

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
  /// Exact friction: the traction proj(λ̂ + r u_T) with `friction_multipliers` λ̂
  /// frozen (null: 0); its semismooth derivative at fixed τ_f goes into `tangent`
  /// (r P at stick, s r (P − t̂ t̂ᵀ) at slip), its τ_f derivative t̂ dτ_f into `coupling`.
  void assemble_newton(const VectorX& u, std::span<const Real> thresholds,
                       const NewtonDuals<dim>& duals, VectorX& internal_force,
                       LinearSystem* tangent = nullptr, UnsymmetricTangent<dim>* coupling = nullptr,
                       const FrictionMultipliers<dim>* friction_multipliers = nullptr) const;

  /// y_f += N x_f for the coupling N of assemble_newton (free dof vectors).
  void apply_coupling(const UnsymmetricTangent<dim>& coupling, const VectorX& x_free,
                      VectorX& y_free) const;

  /// Γ3 quadrature-point state for the velocity `u` (full dof vector); with exact
  /// friction the traction is proj(λ_T + r u_T) for the given (or zero) multipliers.
  std::vector<ContactPoint<dim>>
  contact_state(const VectorX& u, const FrictionMultipliers<dim>* multipliers = nullptr) const;

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
  void attach_multipliers(ConstraintMultipliers<dim>* multipliers) { multipliers_ = multipliers; }
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
  void assemble_contact(Index cell, const std::vector<ContactPoint<dim>>* state,
                        const typename fem::CellValues<dim>::Gradients& coordinates,
                        fem::FacetValues<dim>& facet_values, MatrixX& local_matrix,
                        VectorX& local_load) const;
  /// Adds a cell's load vector (node-major local dofs) to the rhs and, on
  /// prescribed dofs, to LinearSystem::prescribed_loads.
  void scatter_load(Index cell, const VectorX& local_load, LinearSystem& system) const;
  void add_friction_loads(Index cell, const std::vector<ContactPoint<dim>>& state,
                          const typename fem::CellValues<dim>::Gradients& coordinates,
                          fem::FacetValues<dim>& facet_values, LinearSystem& system) const;

  void add_body_force(const fem::CellValues<dim>& values, VectorX& local_load) const;
  void reinit_contact(fem::FacetValues<dim>& values, const Gradients& coordinates,
                      Index position) const {
    discretisation_->reinit_contact(values, coordinates, position);
  }

  const mesh::Mesh<dim>& mesh_;
  ProblemSettings settings_;
  BodyForce<dim> body_force_;
  std::unique_ptr<Discretisation<dim>> discretisation_;
  ConstraintMultipliers<dim>* multipliers_ = nullptr;
};

} // namespace formflow::assembly
