// SPDX-License-Identifier: MIT
// Manufactured solutions: a smooth divergence-free velocity and the body force that
// makes it the exact solution of the penalty problem (SPEC §2, eq. 3.9 with a load).
#pragma once

#include "formflow/physics/flow_law.hpp"

#include <array>

namespace formflow::physics {

/// Which exact solution a verification case uses (case key verification.solution).
enum class ManufacturedSolution {
  None,      ///< not a verification case: the forming process of the case
  Smooth,    ///< uniform extension plus a smooth vortex: curved streamlines, shear
  Extension, ///< uniform extension u = (x, −y): the patch test (reproduced exactly)
};

/// Plane velocity u = (∂ψ/∂y, −∂ψ/∂x) from the stream function
///   ψ = c·x·y + (a/k_y)·sin(k_x x)·sin(k_y y),
/// divergence-free by construction, so that the penalty pressure σ_H = ε̇_V/d
/// of the exact solution is zero for every d. With a·k_x < c the extension
/// rate ∂u_x/∂x stays positive, hence ε̄̇ > 0 everywhere (no degenerate
/// viscosity) and the body force is smooth.
class StreamFunctionField {
public:
  /// c = `extension`, a = `amplitude`, k_x = `wave_x`, k_y = `wave_y`.
  StreamFunctionField(Real extension, Real amplitude, Real wave_x, Real wave_y);
  /// The fields of ManufacturedSolution::Smooth (c = 1, a = 1/4, k = (π, 2π))
  /// and ::Extension (c = 1, a = 0).
  static StreamFunctionField of(ManufacturedSolution solution);

  Point<2> velocity(const Point<2>& x) const;
  /// (∇u)_ij = ∂u_i/∂x_j.
  Tensor2<2> gradient(const Point<2>& x) const;
  /// Second derivatives: hessians[i](j, k) = ∂²u_i/∂x_j∂x_k.
  std::array<Tensor2<2>, 2> hessians(const Point<2>& x) const;

private:
  /// ∂^(m+n)ψ/∂x^m ∂y^n at x, for m + n ≤ 3.
  Real psi(int m, int n, const Point<2>& x) const;
  Real extension_, amplitude_, wave_x_, wave_y_;
};

/// f = −div τ with τ = ⅔ (σ_p(ε̄̇)/ε̄̇) ε̇ (the viscous stress of eq. 3.3) for the
/// field's u: then b(u; u, v) = ∫ f·v for every v vanishing on the boundary,
/// since ε̇_V(u) = 0 removes the penalty term. Evaluated by the chain rule
/// with the field's exact second derivatives; needs ε̄̇(u(x)) > 0.
Point<2> manufactured_body_force(const FlowLaw& law, const StreamFunctionField& field,
                                 const Point<2>& x);

/// The same force from a divergence-free field's gradient (∇u)_ij = ∂u_i/∂x_j and
/// second derivatives hessians[i](j, k) = ∂²u_i/∂x_j∂x_k at one point, in 2D or 3D.
template <int dim>
Point<dim> viscous_body_force(const FlowLaw& law, const Tensor2<dim>& gradient,
                              const std::array<Tensor2<dim>, dim>& hessians);

} // namespace formflow::physics
