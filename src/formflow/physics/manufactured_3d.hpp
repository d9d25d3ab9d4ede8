// SPDX-License-Identifier: MIT
// A three-dimensional manufactured solution: a divergence-free velocity on the unit
// cube and its body force (the 3D twin of physics/manufactured.hpp).
#pragma once

#include "formflow/physics/manufactured.hpp"

#include <array>

namespace formflow::physics {

/// u = c·(x, −y/2, −z/2) + curl A with A = (a/k)·(0, φ, φ),
/// φ = sin(k x) sin(k y) sin(k z): uniaxial extension plus a vortex that depends on
/// all three coordinates, divergence-free by construction (so the penalty pressure
/// of the exact solution vanishes for every d). The extension's strain rate has
/// Frobenius norm c√(3/2); the vortex's entries are at most 2·a·k, so with
/// 3·2ak < c√(3/2) the strain rate never vanishes (ε̄̇ > 0: no degenerate
/// viscosity) — of(Smooth) takes c = 1, a = 0.05, k = π (3·2ak = 0.94 < 1.22).
class VectorPotentialField {
public:
  VectorPotentialField(Real extension, Real amplitude, Real wave);
  /// ManufacturedSolution::Smooth: c = 1, a = 0.05, k = π; ::Extension: a = 0.
  static VectorPotentialField of(ManufacturedSolution solution);

  Point<3> velocity(const Point<3>& x) const;
  /// (∇u)_ij = ∂u_i/∂x_j.
  Tensor2<3> gradient(const Point<3>& x) const;
  /// hessians[i](j, k) = ∂²u_i/∂x_j∂x_k.
  std::array<Tensor2<3>, 3> hessians(const Point<3>& x) const;

private:
  /// ∂^(m₀+m₁+m₂)φ/∂x^m₀∂y^m₁∂z^m₂ at x.
  Real phi(const std::array<int, 3>& order, const Point<3>& x) const;
  /// ∂^order of u_i (one more derivative of φ than u has, through curl A).
  Real velocity_derivative(int i, std::array<int, 3> order, const Point<3>& x) const;
  Real extension_, amplitude_, wave_;
};

/// The body force of VectorPotentialField (manufactured_body_force in 3D).
Point<3> manufactured_body_force(const FlowLaw& law, const VectorPotentialField& field,
                                 const Point<3>& x);

} // namespace formflow::physics
