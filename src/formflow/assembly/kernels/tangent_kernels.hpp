// SPDX-License-Identifier: MIT
// Element kernels of the Newton tangent: what the consistent linearisation of the
// residual adds to the secant matrix of kernels.hpp. Local dof a·dim + i as there.
#pragma once

#include "formflow/fem/cell_values.hpp"

#include <span>

namespace formflow::assembly {

/// (1′) Derivative of the secant viscosity in a(u; u, v) with respect to u, in the
/// primal–dual form (Chan–Golub–Mulet for TV; Rudi, Shih & Stadler 2017 for
/// viscoplastic Stokes): with g = ė(u):ε̇(·), h = w:ε̇(·) and a dual stress w,
///   ∫ [a gᵀ g + b ½(h ⊗ g + g ⊗ h)] dx,  a = (4/9) σ_p′/ε̄̇²,  b = −(4/9)/ε̄̇².
/// For w = ν ė (the primal choice) this is the exact derivative (4/9)(σ_p′ − ν)/ε̄̇²
/// g ⊗ g, from dε̄̇[δu] = ⅔ ė(u):ė(δu)/ε̄̇; added to the secant term it gives ⅔ σ_p′
/// along ė(u) and ⅔ ν across it. It stays positive semi-definite whenever
/// √(⅔ w:w) ≤ σ_p(ε̄̇) (Cauchy–Schwarz), which the dual update enforces.
/// `deviators[q]` is ė(u), `duals[q]` is w (trace free); a, b per point.
template <int dim>
void add_viscous_tangent(const fem::CellValues<dim>& values, std::span<const Tensor3> deviators,
                         std::span<const Tensor3> duals, std::span<const Real> a,
                         std::span<const Real> b, MatrixX& local_matrix);

/// (1′) in axisymmetry (y = r, `values` r-weighted): the same with the hoop
/// slot, ė(u):ε̇(φ_a e_r) += ė_θθ φ_a/r and likewise for w.
void add_viscous_tangent_axisymmetric(const fem::CellValues<2>& values,
                                      std::span<const Tensor3> deviators,
                                      std::span<const Tensor3> duals, std::span<const Real> a,
                                      std::span<const Real> b, MatrixX& local_matrix);

/// (4′) Derivative of the regularised friction force τ_f u_T/s, s = √(|u_T|² + d_T²),
/// with respect to u_T at fixed τ_f, primal–dual form with λ ≈ u_T/s:
///   −∫ τ_f/s² ½[(λ·v_T)(u_T·δu_T) + (u_T·v_T)(λ·δu_T)] dΓ.
/// For λ = u_T/s it is the exact −τ_f/s³ (u_T·v_T)(u_T·δu_T); with the secant
/// term τ_f/s δu_T·v_T it stays positive semi-definite for |λ| ≤ 1.
/// `slip[q]` is u_T, `dual_slip[q]` is s λ, `coefficient[q]` is τ_f/s³.
template <int dim>
void add_friction_tangent(const fem::FacetValues<dim>& values, std::span<const Point<dim>> slip,
                          std::span<const Point<dim>> dual_slip, std::span<const Real> coefficient,
                          MatrixX& local_matrix);

} // namespace formflow::assembly
