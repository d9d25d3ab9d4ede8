// SPDX-License-Identifier: MIT
// The mixed formulation's multipliers: the hydrostatic stress σ_H in a
// discontinuous pressure space, condensed cell by cell, and the exact-constraint
// (augmented-Lagrangian) multipliers of incompressibility and contact (issue 5).
#pragma once

#include "formflow/assembly/distribution.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/pressure_space.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/physics/process.hpp"

#include <functional>
#include <span>
#include <vector>

namespace formflow::assembly {

enum class FormulationType { Penalty, Mixed };

/// How a discontinuous pressure (P0, P1disc) is solved: eliminated cell by cell
/// (velocity-only SPD systems), or kept as global unknowns of a saddle point (its
/// dofs numbered cell·n_p + k), which an iterative block preconditioner needs.
enum class DiscontinuousPressure { Condensed, SaddlePoint };

/// Which problem is discretised (SPEC §2): the penalty problem (3.9) with σ_H
/// at the volumetric points, or the perturbed mixed problem (3.7) with σ_H in
/// `pressure`. penalty.d = 0 (mixed only) and penalty.dN = 0 select the exact
/// constraints, enforced by augmented-Lagrangian (Uzawa) steps.
struct Formulation {
  FormulationType type = FormulationType::Penalty;
  fem::PressureSpace pressure = fem::PressureSpace::P1disc;
  /// formulation.discontinuous_pressure (read for P0 and P1disc only).
  DiscontinuousPressure discontinuous = DiscontinuousPressure::Condensed;
  /// ρ of the augmented-Lagrangian term when d = 0: per cell r_e = ρ ν̄_e with ν̄_e
  /// the cell's mean secant viscosity, so that every cell's constraint converges
  /// at the rate ≈ 1/(1 + ρ β_h²) whatever its viscosity.
  Real augmentation = 1e3;
  Real contact_augmentation = 1e6; ///< r_N of the contact term when d_N = 0 (like 1/d_N)
  Real uzawa_tolerance = 1e-8;     ///< relative multiplier change that ends the Uzawa steps
  int uzawa_max_steps = 50;        ///< Uzawa steps per secant iteration
};

/// Per-cell matrices of the discontinuous pressure space and the multiplier state.
///
/// Mixed problem (3.7) on one cell with pressure coefficients c:
///   a(u, v) + cᵀ B v = f(v),   B u − d M c = 0,
/// B_ia = ∫ ψ_i div φ_a dx, M_ij = ∫ ψ_i ψ_j dx. For d > 0 the pressure is
/// condensed, c = (1/d) M⁻¹ B u, and the cell adds (1/d) Bᵀ M⁻¹ B to the SPD
/// velocity matrix. For d = 0 the cell adds r_e Bᵀ M⁻¹ B and the load −Bᵀ λ_e,
/// and each Uzawa step sets λ_e ← λ_e + r_e M⁻¹ B u_e (fixed point: M⁻¹ B u = 0).
/// Exact contact (d_N = 0) is the same at each Γ3 quadrature point: the term
/// r_N u_N v_N, the load −λ_k v_N and λ_k ← λ_k + r_N u_N(x_k) (−σ_N = λ).
/// A continuous pressure (Q1, Taylor–Hood) uses the same cell B and M but is not
/// condensed: its vertex values are global unknowns of the saddle-point system
/// (assembly/saddle_point_system.hpp), stored here; the cell adds only −Bᵀp.
template <int dim> class ConstraintMultipliers {
public:
  /// `full_rule` integrates B and M exactly on affine cells; `n_contact_points`
  /// is the number of Γ3 quadrature points (FormingProblem::contact_state order).
  /// `axisymmetric` (y = r): the integrals are per radian (dx = r dr dz) and the
  /// divergence has the hoop rate, div(φ_a e_r) = ∂_r φ_a + φ_a/r.
  ConstraintMultipliers(const mesh::Mesh<dim>& mesh, const physics::Penalty& penalty,
                        const Formulation& formulation, const fem::QuadratureRule<dim>& full_rule,
                        Index n_contact_points, bool axisymmetric = false);

  bool has_pressure_space() const { return formulation_.type == FormulationType::Mixed; }
  /// Global pressure dofs solved together with the velocity
  /// (assembly/saddle_point_system.*), never condensed; d = 0 then needs no Uzawa
  /// steps. A continuous pressure (Taylor–Hood Q2–Q1) always has them (on the cell
  /// vertices); a discontinuous one when formulation.discontinuous_pressure says
  /// "saddle_point" (cell·n_p + k).
  bool has_global_pressure() const {
    return has_pressure_space() &&
           (!fem::is_discontinuous(formulation_.pressure) ||
            formulation_.discontinuous == DiscontinuousPressure::SaddlePoint);
  }
  bool is_exact_pressure() const { return has_pressure_space() && penalty_.d == 0; }
  bool is_exact_contact() const { return penalty_.d_n == 0; }
  /// True when Uzawa steps are needed (some constraint is exact and not solved directly).
  bool needs_uzawa() const {
    return (is_exact_pressure() && !has_global_pressure()) || is_exact_contact();
  }
  /// True when the pressure is condensed with d > 0 and no constraint is exact: the
  /// mixed term is then the fixed SPD matrix (1/d) Bᵀ M⁻¹ B per cell, linear in u,
  /// so Newton's tangent and residual take it as it is (no multiplier loop).
  bool is_condensed_penalty() const {
    return has_pressure_space() && !has_global_pressure() && !needs_uzawa();
  }
  /// True when the cell loop must scatter the local loads (multiplier loads −Bᵀλ,
  /// −λ_N v_N, or the global pressure's −Bᵀp).
  bool has_cell_loads() const { return needs_uzawa() || has_global_pressure(); }

  /// The weak-form terms of these multipliers (assembly/terms/*_pressure_term.cpp,
  /// augmented_contact_term.cpp) read the per-cell matrices and multipliers here.
  /// M⁻¹ of `cell`.
  const MatrixX& cell_inverse_mass(Index cell) const { return inverse_mass_[cell]; }
  /// ∫ ψ_i dx of `cell`.
  const VectorX& cell_basis_integral(Index cell) const { return basis_integral_[cell]; }
  /// λ_e of `cell` (d = 0).
  const VectorX& cell_multiplier(Index cell) const { return multiplier_[cell]; }
  /// d = 0: sets and returns r_e = ρ ν̄_e for the cell's mean secant viscosity ν̄_e,
  /// remembered for the next update (so update after assembling).
  Real record_augmentation(Index cell, Real mean_viscosity) {
    return augmentation_[cell] = formulation_.augmentation * mean_viscosity;
  }
  /// σ_H coefficients of `cell` for its node-major local velocity.
  VectorX cell_pressure_coefficients(Index cell, const Eigen::Ref<const VectorX>& velocity) const;
  /// Exact contact: λ_k at Γ3 point k, and its quadrature weight, recorded by the
  /// assembly for the L² norm of the update.
  Real contact_multiplier(Index k) const { return contact_multiplier_[k]; }
  void record_contact_weight(Index k, Real weight) { contact_weight_[k] = weight; }

  /// One Uzawa step from velocity `u` and the Γ3 normal velocities
  /// (contact_state order). Returns the relative change of the multipliers
  /// (the larger of pressure and contact), 0 when nothing is exact.
  /// Distributed (issue 20): `u` is ghosted and the assembly recorded r_e and the Γ3
  /// weights for the rank's own cells (`cell_ranks`, `distribution.rank`) only: each
  /// rank steps its own cells' λ_e, the changes' norms and the cells' λ_e and r_e are
  /// summed over the ranks (each cell one rank's, so every rank gets the owner's bits),
  /// and the Γ3 weights are summed before the (whole, alike) contact step.
  Real update(const VectorX& u, std::span<const Real> normal_velocity,
              const std::vector<int>& cell_ranks = {}, const Distribution& distribution = {});

  /// σ_H coefficients of `cell` at velocity `u` (length pressure_functions_per_cell).
  VectorX pressure_coefficients(Index cell, const VectorX& u) const;
  /// ∫_cell σ_H dx at velocity `u`.
  Real pressure_integral(Index cell, const VectorX& u) const;
  /// Contact pressure −σ_N at Γ3 point `k` with normal velocity `normal_velocity`.
  Real contact_pressure(Index k, Real normal_velocity) const;
  fem::PressureSpace pressure_space() const { return formulation_.pressure; }

  /// Global pressure: σ_H coefficients of `cell` (its vertex values).
  VectorX cell_pressure(Index cell) const;
  /// Global pressure (has_global_pressure only). Pressure dof of the cell's basis
  /// function i (vertex i, lexicographic; length pressure_functions_per_cell).
  std::span<const Index> cell_pressure_dofs(Index cell) const {
    const auto size = static_cast<std::size_t>(n_pressure_);
    return {pressure_dofs_.data() + static_cast<std::size_t>(cell) * size, size};
  }
  Index n_pressure_dofs() const { return n_pressure_dofs_; }
  /// The global pressure's coefficients (length n_pressure_dofs): vertex values of
  /// σ_H (Q1), or each cell's coefficients of its monomials (P0, P1disc).
  const VectorX& global_pressure() const { return pressure_; }
  /// The coefficients of σ_H ≡ 1 in the global pressure: all ones for the vertex
  /// functions (a partition of unity), the constant monomial of each cell otherwise.
  VectorX constant_pressure() const;
  /// The Schur-complement preconditioner's cell block ∫ ψ_i ψ_j / (2η) dx, 2η = ⅔ ν the
  /// secant viscosity at each full-rule point of the last assembly (η the Stokes
  /// viscosity of a(w; u, v) = ∫ ⅔ ν ε̇:ε̇: σ = 2η ε̇); recorded by the global pressure
  /// term, read by SaddlePointSystem::schur_preconditioner.
  void record_viscous_mass(Index cell, const fem::CellValues<dim>& full,
                           std::span<const Real> viscosity);
  const MatrixX& cell_viscous_mass(Index cell) const { return viscous_mass_[cell]; }
  void set_global_pressure(VectorX pressure) { pressure_ = std::move(pressure); }
  /// B = ∫ ψ_i div φ_a dx (n_pressure × n_local) and M = ∫ ψ_i ψ_j dx of `cell`.
  const MatrixX& cell_divergence(Index cell) const { return divergence_[cell]; }
  const MatrixX& cell_mass(Index cell) const { return mass_[cell]; }
  const Formulation& formulation() const { return formulation_; }
  const physics::Penalty& penalty() const { return penalty_; }

private:
  /// Every cell's λ_e and r_e from the rank that owns the cell (`own`), summed over the
  /// ranks (collective).
  void gather_cell_multipliers(const std::function<bool(Index)>& own,
                               const Distribution& distribution);
  VectorX cell_velocity(Index cell, const VectorX& u) const;
  /// Global pressure: numbers the cell vertices (on first sight) into pressure_dofs_.
  void number_vertices();
  /// Global discontinuous pressure: cell·n_p + k.
  void number_cells();

  const mesh::Mesh<dim>& mesh_;
  physics::Penalty penalty_;
  Formulation formulation_;
  int n_pressure_ = 0;
  std::vector<MatrixX> divergence_; ///< B per cell, n_pressure × n_local
  std::vector<MatrixX> mass_, inverse_mass_;
  std::vector<VectorX> basis_integral_;  ///< ∫ ψ_i dx per cell
  std::vector<VectorX> multiplier_;      ///< λ per cell (d = 0)
  std::vector<Real> augmentation_;       ///< r_e per cell from the last assembly (d = 0)
  std::vector<Real> contact_multiplier_; ///< λ_k per Γ3 point (d_N = 0)
  std::vector<Real> contact_weight_; ///< JxW per Γ3 point, filled by the augmented contact term
  /// Distributed: contact_weight_ was summed over the ranks (the weights are geometry:
  /// every assembly records the same ones, so one sum serves).
  bool contact_weights_summed_ = false;
  std::vector<Index> pressure_dofs_; ///< global pressure: n_pressure per cell, cell-major
  Index n_pressure_dofs_ = 0;
  VectorX pressure_;                     ///< global pressure: vertex values of σ_H
  std::vector<VectorX> basis_at_points_; ///< ψ at the full-rule points (global pressure)
  std::vector<MatrixX> viscous_mass_;    ///< ∫ ψψ/(2η) per cell (global pressure)
};

} // namespace formflow::assembly
