// SPDX-License-Identifier: MIT
// The weak-form terms formflow knows, one file each (terms/<name>_term.cpp), and the
// registration that picks a problem's terms (terms/term_set.cpp).
#pragma once

#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/terms/term.hpp"
#include "formflow/physics/flow_law.hpp"
#include "formflow/physics/friction.hpp"

#include <functional>
#include <memory>

namespace formflow::assembly {

/// A volume load f(x) per unit volume (manufactured solutions): adds ∫ f·v dx to F.
template <int dim> using BodyForce = std::function<Point<dim>(const Point<dim>&)>;

/// (1) a(w; u, v) = ∫ ⅔ ν(ε̄̇(w)) ε̇(u):ε̇(v) dx (eq. 3.3), with the hoop slot in axisymmetry.
template <int dim>
std::unique_ptr<CellTerm<dim>> make_viscous_term(const physics::FlowLaw& law,
                                                 physics::ViscousStrain strain, bool axisymmetric);
/// (2) ∫ (1/d) ε̇_V(u) ε̇_V(v) dx on the volumetric rule (eq. 3.8); σ_H = ε̇_V/d.
template <int dim>
std::unique_ptr<CellTerm<dim>> make_volumetric_penalty_term(Real d, bool axisymmetric, int order,
                                                            int volumetric_points);
/// The mixed problem's discontinuous pressure condensed at d > 0: (1/d) Bᵀ M⁻¹ B per cell.
template <int dim>
std::unique_ptr<CellTerm<dim>> make_condensed_pressure_term(ConstraintMultipliers<dim>& pressure,
                                                            const mesh::CellType& type);
/// The discontinuous pressure at d = 0: r_e Bᵀ M⁻¹ B and the load −Bᵀ λ_e (Uzawa).
template <int dim>
std::unique_ptr<CellTerm<dim>> make_augmented_pressure_term(ConstraintMultipliers<dim>& pressure,
                                                            const mesh::CellType& type);
/// A continuous pressure (Taylor–Hood): the load −Bᵀ p of the saddle-point system.
template <int dim>
std::unique_ptr<CellTerm<dim>> make_global_pressure_term(ConstraintMultipliers<dim>& pressure,
                                                         const mesh::CellType& type);
/// ∫ f·v dx.
template <int dim> std::unique_ptr<CellTerm<dim>> make_body_force_term(BodyForce<dim> force);

/// (3) ∫_Γ3 (1/d_N) u_N v_N dΓ (eq. 3.8).
template <int dim> std::unique_ptr<FaceTerm<dim>> make_contact_penalty_term(Real d_n);
/// Exact contact (d_N = 0): r_N u_N v_N and the load −λ v_N per Γ3 point (Uzawa).
template <int dim>
std::unique_ptr<FaceTerm<dim>> make_augmented_contact_term(ConstraintMultipliers<dim>& contact);
/// (4) friction, threshold × enforcement (regularised with d_T, or exact with the
/// augmentation r): the traction λ_T of each ContactPoint.
template <int dim>
std::unique_ptr<FaceTerm<dim>> make_friction_term(const physics::Friction& friction,
                                                  Real augmentation);

} // namespace formflow::assembly
