// SPDX-License-Identifier: MIT
// Strain rate, its deviator and the equivalent strain rate (SPEC §1, eq. 2.1).
#pragma once

#include "formflow/core/types.hpp"

#include <cmath>

namespace formflow::physics {

/// ε̇ = ½(∇u + ∇uᵀ) as a 3×3 tensor from the dim×dim velocity gradient
/// (∇u)_ij = ∂u_i/∂x_j. Plane strain (dim = 2) leaves ε̇_zz = 0.
template <int dim> Tensor3 strain_rate(const Tensor2<dim>& velocity_gradient) {
  Tensor3 rate = Tensor3::Zero();
  rate.template topLeftCorner<dim, dim>() =
      0.5 * (velocity_gradient + velocity_gradient.transpose());
  return rate;
}

/// Velocity gradient (∇u)_ij = Σ_a u_ia ∂N_a/∂x_j from nodal velocities
/// (dim × n_nodes) and shape gradients (dim × n_nodes).
template <int dim, typename Velocities, typename Gradients>
Tensor2<dim> velocity_gradient(const Velocities& nodal_velocity, const Gradients& gradients) {
  return nodal_velocity * gradients.transpose();
}

/// Axisymmetric hoop rate ε̇_θθ = u_r/r at radius r = y; on the axis (r → 0,
/// where u_r = 0) its limit ∂u_r/∂r.
template <int dim>
void add_hoop_rate(Tensor3& rate, const Tensor2<dim>& velocity_gradient, Real radial_velocity,
                   Real radius) {
  rate(2, 2) = radius > 1e-12 ? radial_velocity / radius : velocity_gradient(1, 1);
}

/// Volumetric rate ε̇_V = tr ε̇.
inline Real volumetric_rate(const Tensor3& rate) {
  return rate.trace();
}

/// Deviator ė = ε̇ − ⅓ ε̇_V I (ė_zz = −⅓ ε̇_V in plane strain).
inline Tensor3 deviator(const Tensor3& rate) {
  return rate - (rate.trace() / 3.0) * Tensor3::Identity();
}

/// Equivalent strain rate ε̄̇ = √(⅔ ė:ė).
inline Real equivalent_strain_rate(const Tensor3& rate) {
  const Tensor3 dev = deviator(rate);
  return std::sqrt(2.0 / 3.0 * dev.cwiseProduct(dev).sum());
}

} // namespace formflow::physics
