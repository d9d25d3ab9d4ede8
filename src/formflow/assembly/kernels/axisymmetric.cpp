// SPDX-License-Identifier: MIT
// Hoop-strain terms of the axisymmetric forms (y = r, integrals per radian).
#include "formflow/assembly/kernels/kernels.hpp"

namespace formflow::assembly {

// For φ_a e_i: ε̇_θθ = δ_i1 φ_a/r and ε̇_V = ∂_i φ_a + δ_i1 φ_a/r. The plane
// kernel gives the in-plane ε̇:ε̇ − s ∂_iφ_a ∂_jφ_b (s = ⅓ for the deviator);
// this adds ε̇_θθ ε̇_θθ and the cross terms of −s ε̇_V(u) ε̇_V(v) that involve the hoop rate.
void add_hoop_viscous_term(const fem::CellValues<2>& values, std::span<const Real> viscosity,
                           physics::ViscousStrain strain, MatrixX& local_matrix) {
  const int n = values.n_nodes();
  const Real share = strain == physics::ViscousStrain::Deviatoric ? 1.0 / 3.0 : 0.0;
  for (int q = 0; q < values.n_points(); ++q) {
    const auto& grad = values.gradients(q);
    const CellVector hoop = values.shape(q) / values.point(q)[1]; // φ_a/r
    const Real factor = 2.0 / 3.0 * viscosity[q] * values.JxW(q);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        local_matrix(a * 2 + 1, b * 2 + 1) += factor * (1.0 - share) * hoop[a] * hoop[b];
        if (share == 0.0) continue;
        for (int j = 0; j < 2; ++j)
          local_matrix(a * 2 + 1, b * 2 + j) -= factor * share * hoop[a] * grad(j, b);
        for (int i = 0; i < 2; ++i)
          local_matrix(a * 2 + i, b * 2 + 1) -= factor * share * grad(i, a) * hoop[b];
      }
  }
}

void add_volumetric_penalty_axisymmetric(const fem::CellValues<2>& values, Real d,
                                         MatrixX& local_matrix) {
  const int n_local = values.n_nodes() * 2;
  CellVector divergence(n_local);
  for (int q = 0; q < values.n_points(); ++q) {
    const auto& grad = values.gradients(q);
    const Real radius = values.point(q)[1];
    for (int a = 0; a < values.n_nodes(); ++a) {
      divergence[a * 2] = grad(0, a);
      divergence[a * 2 + 1] = grad(1, a) + values.shape(q)[a] / radius;
    }
    local_matrix.noalias() += (values.JxW(q) / d) * divergence * divergence.transpose();
  }
}

} // namespace formflow::assembly
