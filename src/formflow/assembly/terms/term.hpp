// SPDX-License-Identifier: MIT
// Weak-form terms: each term of b(w; u, v) + ⟨j′⟩ (SPEC §2–3) as one object that
// gives, for one cell or one contact face, its secant matrix and loads, its
// internal force at u, what Newton's consistent linearisation adds, its power
// and (for the term that carries σ_H) the hydrostatic stress. The assembler
// (assembly/assembler.hpp) runs one loop over the cells and asks every term; no
// other code writes a weak-form term.
#pragma once

#include "formflow/assembly/contact_point.hpp"
#include "formflow/fem/cell_values.hpp"

#include <span>
#include <string_view>
#include <vector>

namespace formflow::assembly {

/// Powers (per unit depth, or per radian) of each discrete term at one velocity.
struct PowerTerms {
  Real plastic_dissipation = 0.0; ///< ∫ σ_p(ε̄̇) ε̄̇ dx
  Real viscous_form = 0.0;        ///< a(u; u, u) (≥ dissipation when the full ε̇ is used)
  Real volumetric_penalty = 0.0;  ///< ∫ σ_H ε̇_V dx: ∫ ε̇_V²/d dx for the penalty
  Real contact_penalty = 0.0;     ///< ∫_Γ3 −σ_N u_N dΓ: ∫ u_N²/d_N dΓ for the penalty
  Real friction = 0.0; ///< ∫_Γ3 λ_T·u_T dΓ (regularised: τ_f |u_T|²/√(|u_T|² + d_T²))
  Real total() const { return viscous_form + volumetric_penalty + contact_penalty + friction; }
};

/// The Newton tangent's per-point coefficients of the viscous law (tangent passes only):
/// ė(u), the dual stress w, a = (4/9) σ_p′/ε̄̇², b = −(4/9)/ε̄̇² (kernels/tangent_kernels.hpp).
struct ViscousTangentData {
  std::span<const Tensor3> deviators, duals;
  std::span<const Real> a, b;
};

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

/// One cell at one velocity, as the assembler prepared it for every cell term.
template <int dim> struct CellState {
  using Gradients = typename fem::CellValues<dim>::Gradients;
  Index cell = 0;
  const fem::CellValues<dim>& full;       ///< mapped values at the full (a-term) rule
  const fem::CellValues<dim>& volumetric; ///< mapped values at the volumetric rule
  const Gradients& coordinates;           ///< node coordinates (dim × n)
  const Gradients& velocities;            ///< nodal velocities (dim × n; zero at the start)
  std::span<const Real> viscosity;        ///< secant ν at the full-rule points
  std::span<const Tensor3> rates;         ///< ε̇ at the full-rule points (force, tangent, power)
  ViscousTangentData tangent;             ///< tangent passes only
  /// Hot forming: the temperature at each full-rule point, at which the flow law is taken
  /// (empty: the isothermal law, whose own parameters hold its temperature).
  std::span<const Real> temperatures = {};
  /// The nodal velocities as one node-major local vector (local dof a·dim + i).
  Eigen::Map<const VectorX> local_velocity() const {
    return {velocities.data(), velocities.size()};
  }
};

/// One Γ3 face of a cell at one velocity.
template <int dim> struct FaceState {
  using Gradients = typename fem::CellValues<dim>::Gradients;
  Index cell = 0;
  Index position = 0;                  ///< index into Discretisation::contact_facets()
  const fem::FacetValues<dim>& values; ///< mapped, with the contact normals
  const Gradients& velocities;
  /// The face's Γ3 points (ContactPoint) in face-rule order; empty when the pass has no
  /// contact state (the constant-viscosity start: τ_f(0) = 0, no friction).
  std::span<const ContactPoint<dim>> points;
  /// Newton's slip duals λ at the face's points (empty: the primal choice).
  std::span<const Point<dim>> slip_duals;
  Index first_point() const { return position * values.n_points(); }
};

/// σ_H of one cell, from the term that carries the pressure.
struct CellPressure {
  Real integral = 0.0; ///< ∫_cell σ_H dx
  VectorX at_nodes;    ///< σ_H at the cell's nodes (local order)
};

/// The unsymmetric part of the Newton Jacobian, applied matrix free (the symmetric rest
/// is the assembled tangent). Filled by the terms that have one:
///  * the viscous term with the paper's full-ε̇ a-form: ∫ c ε̇_V(v) (ė(u):ε̇(δu)) dx,
///    kept per full-rule point where c ≠ 0 as c·JxW, the divergence row ε̇_V(φ) and
///    the row ė(u):ε̇(φ) over the cell's local dofs (a·dim + i);
///  * the friction term for a pressure-dependent threshold: ∫_Γ3 dτ_f[δu] ĝ·v_T dΓ with
///    dτ_f = (∂τ_f/∂σ̄_N) dσ̄_N, kept per Γ3 point as (∂τ_f/∂σ̄_N) ĝ (0 elsewhere),
///    ĝ the direction of the friction force.
template <int dim> struct UnsymmetricTangent {
  int n_local = 0;
  std::vector<Index> cells;               ///< cell of each kept point
  std::vector<Real> coefficients;         ///< c·JxW per kept point
  std::vector<Real> rows;                 ///< per kept point: divergence row, then ė(u) row
  std::vector<Point<dim>> threshold_slip; ///< per Γ3 point (contact_state() order)
  bool has_friction = false;              ///< some threshold_slip ≠ 0
  /// The assembly's cell schedule (assembly/cell_schedule.hpp) over the kept points: for
  /// each phase, where each of its blocks' points start, then the phase's end. Blocks of
  /// one phase share no dof, so their products may run at the same time. Empty: the
  /// points were kept in one sweep (no schedule).
  std::vector<std::vector<std::size_t>> phase_starts;
  void clear() {
    cells.clear(), coefficients.clear(), rows.clear(), threshold_slip.clear(), has_friction = false;
    phase_starts.clear();
  }
  bool empty() const { return cells.empty() && !has_friction; }
};

/// What Newton's assembly hands the terms before its cell loop: the contact state may
/// be changed in place (frozen thresholds), the coupling filled.
template <int dim> struct NewtonPass {
  std::vector<ContactPoint<dim>>& contact;
  std::span<const Real> thresholds; ///< τ_f frozen per Γ3 point
  /// Exact friction's frozen multipliers λ̂ per Γ3 point (empty: 0).
  std::span<const Point<dim>> friction_multipliers;
  UnsymmetricTangent<dim>* coupling; ///< null: no coupling wanted
};

/// A term integrated over the cells.
template <int dim> class CellTerm {
public:
  virtual ~CellTerm() = default;
  virtual std::string_view name() const = 0;
  /// Adds the secant matrix K_e(w) and the loads F_e (right-hand side) of the cell.
  virtual void add_secant(const CellState<dim>& cell, MatrixX& matrix, VectorX& load) const = 0;
  /// Adds the internal force K_e(u) u_e − F_e at the velocity of `cell`, without a matrix.
  virtual void add_force(const CellState<dim>& cell, CellVector& force) const = 0;
  /// Adds what the consistent linearisation adds to the secant matrix (symmetric part).
  virtual void add_tangent(const CellState<dim>&, MatrixX&) const {}
  /// Appends the unsymmetric rest of the linearisation (UnsymmetricTangent).
  virtual void add_coupling(const CellState<dim>&, UnsymmetricTangent<dim>&) const {}
  /// Adds the term's power at the velocity of `cell`.
  virtual void add_power(const CellState<dim>& cell, PowerTerms& power) const = 0;
  /// True when the term puts loads into F (multipliers, a body force): the assembler
  /// scatters the local load vector only then.
  virtual bool has_loads() const { return false; }
  /// True for the one term whose multiplier is σ_H (penalty or pressure space).
  virtual bool carries_pressure() const { return false; }
  virtual CellPressure pressure(const CellState<dim>&) const { return {}; }
  /// False when Newton cannot linearise the term (Uzawa multipliers, global pressure).
  virtual bool newton_ready() const { return true; }
};

/// A term integrated over the contact faces Γ3.
template <int dim> class FaceTerm {
public:
  virtual ~FaceTerm() = default;
  virtual std::string_view name() const = 0;
  virtual void add_secant(const FaceState<dim>& face, MatrixX& matrix, VectorX& load) const = 0;
  virtual void add_force(const FaceState<dim>& face, CellVector& force) const = 0;
  virtual void add_tangent(const FaceState<dim>&, MatrixX&) const {}
  virtual void add_power(const FaceState<dim>& face, PowerTerms& power) const = 0;
  /// Newton: prepares the contact state before the cell loop (frozen thresholds,
  /// the coupling of the threshold).
  virtual void begin_newton(NewtonPass<dim>&) const {}
  virtual bool has_loads() const { return false; }
  virtual bool newton_ready() const { return true; }
};

} // namespace formflow::assembly
