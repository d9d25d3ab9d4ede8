// SPDX-License-Identifier: MIT
// Element kernels of the residual alone: K(u) u of kernels.hpp's terms at the
// velocity u itself, without forming a local matrix (the Newton line search
// needs only the residual at each trial point). Local dof a·dim + i as there.
#pragma once

#include "formflow/fem/cell_values.hpp"
#include "formflow/physics/process.hpp"

#include <span>

namespace formflow::assembly {

/// (1) at u: ∫ ⅔ ν ε̇(u):ε̇(φ_a e_i) dx = ∫ ⅔ ν (ε̇(u) ∇φ_a)_i dx, with the
/// deviator ė(u) for ViscousStrain::Deviatoric. `rates[q]` is ε̇(u) at point q
/// (in axisymmetry with ε̇_θθ, which enters here through ε̇_V only).
template <int dim>
void add_viscous_force(const fem::CellValues<dim>& values, std::span<const Real> viscosity,
                       std::span<const Tensor3> rates, physics::ViscousStrain strain,
                       CellVector& local_force);

/// (2) at u: ∫ (1/d) ε̇_V(u) ∂_i φ_a dx on the volumetric rule of `values`, for
/// the cell's nodal velocities (dim × n_nodes).
template <int dim>
void add_volumetric_force(const fem::CellValues<dim>& values, Real d,
                          const typename fem::CellValues<dim>::Gradients& velocities,
                          CellVector& local_force);

/// (3) at u on one contact face: ∫_Γ3 (1/d_N) u_N n·φ_a e_i dΓ (friction's force is
/// the friction term's, terms/friction_term.cpp).
template <int dim>
void add_contact_force(const fem::FacetValues<dim>& values, Real d_n,
                       const typename fem::CellValues<dim>::Gradients& velocities,
                       CellVector& local_force);

} // namespace formflow::assembly

namespace formflow::assembly {

/// Axisymmetry (y = r, `values` r-weighted): the hoop part of add_viscous_force,
/// ∫ ⅔ ν (ε̇_θθ − share ε̇_V) φ_a/r dx on the radial component (share = ⅓ for
/// the deviatoric form, 0 for the full one); `rates[q]` carries ε̇_θθ = u_r/r.
void add_hoop_viscous_force(const fem::CellValues<2>& values, std::span<const Real> viscosity,
                            std::span<const Tensor3> rates, physics::ViscousStrain strain,
                            CellVector& local_force);

/// Axisymmetry: add_volumetric_force with ε̇_V = ∂_x u_x + ∂_r u_r + u_r/r and
/// ε̇_V(φ_a e_i) = ∂_i φ_a + δ_ir φ_a/r, replacing it.
void add_volumetric_force_axisymmetric(const fem::CellValues<2>& values, Real d,
                                       const fem::CellValues<2>::Gradients& velocities,
                                       CellVector& local_force);

} // namespace formflow::assembly
