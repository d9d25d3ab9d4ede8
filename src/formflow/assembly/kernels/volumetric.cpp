// SPDX-License-Identifier: MIT
// Penalty incompressibility term (SPEC §2, eq. 3.8), with its own quadrature rule.
#include "formflow/assembly/kernels/kernels.hpp"

namespace formflow::assembly {

template <int dim>
void add_volumetric_penalty(const fem::CellValues<dim>& values, Real d, MatrixX& local_matrix) {
  const int n_local = values.n_nodes() * dim;
  for (int q = 0; q < values.n_points(); ++q) {
    // ε̇_V(φ_a e_i) = ∂_i φ_a: the flattened gradient is the divergence row.
    const auto& grad = values.gradients(q);
    const Eigen::Map<const VectorX> divergence(grad.data(), n_local);
    local_matrix.noalias() += (values.JxW(q) / d) * divergence * divergence.transpose();  // (1/d) dx
  }
}

template void add_volumetric_penalty<2>(const fem::CellValues<2>&, Real, MatrixX&);
template void add_volumetric_penalty<3>(const fem::CellValues<3>&, Real, MatrixX&);

}  // namespace formflow::assembly
