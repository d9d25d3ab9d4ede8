// SPDX-License-Identifier: MIT
// Element kernels: each adds one term of the linearised form b(w; u, v) + ⟨j′⟩ to a
// local matrix. Local dof a·dim + i is component i at local node a (fem/dof_map.hpp).
#pragma once

#include "formflow/fem/cell_values.hpp"
#include "formflow/physics/process.hpp"

#include <span>

namespace formflow::assembly {

/// (1) a(w; u, v) = ∫ ⅔ ν(ε̄̇(w)) ε̇(u):ε̇(v) dx (eq. 3.3), ν = σ_p/ε̄̇ given per
/// point in `viscosity`; with ViscousStrain::Deviatoric the deviators ė replace ε̇.
template <int dim>
void add_viscous_term(const fem::CellValues<dim>& values, std::span<const Real> viscosity,
                      physics::ViscousStrain strain, MatrixX& local_matrix);

/// (2) ∫ (1/d) ε̇_V(u) ε̇_V(v) dx, integrated with the volumetric rule of `values` (eq. 3.8).
template <int dim>
void add_volumetric_penalty(const fem::CellValues<dim>& values, Real d, MatrixX& local_matrix);

/// (3) ∫_Γ3 (1/d_N) u_N v_N dΓ on one contact face (eq. 3.8).
template <int dim>
void add_contact_penalty(const fem::FacetValues<dim>& values, Real d_n, MatrixX& local_matrix);

/// (4) ∫_Γ3 κ u_T·v_T dΓ with κ = τ_f(w)/√(|w_T|² + d_T²) per face point (eq. 5.3).
template <int dim>
void add_friction_term(const fem::FacetValues<dim>& values, std::span<const Real> weight,
                       MatrixX& local_matrix);

/// Axisymmetry (y = r, `values` r-weighted): the hoop part of (1) that
/// add_viscous_term leaves out, ε̇_θθ(φ_a e_r) = φ_a/r (kernels/axisymmetric.cpp).
void add_hoop_viscous_term(const fem::CellValues<2>& values, std::span<const Real> viscosity,
                           physics::ViscousStrain strain, MatrixX& local_matrix);

/// Axisymmetry: (2) with ε̇_V = ∂_x u_x + ∂_r u_r + u_r/r, replacing add_volumetric_penalty.
void add_volumetric_penalty_axisymmetric(const fem::CellValues<2>& values, Real d,
                                         MatrixX& local_matrix);

} // namespace formflow::assembly
