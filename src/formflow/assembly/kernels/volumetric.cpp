// SPDX-License-Identifier: MIT
// Penalty incompressibility term (SPEC §2, eq. 3.8), with its own quadrature rule.
#include "formflow/assembly/kernels/fixed_size.hpp"
#include "formflow/assembly/kernels/kernels.hpp"

namespace formflow::assembly {

namespace {

template <int dim, int n_nodes>
void add_volumetric_penalty_sized(const fem::CellValues<dim>& values, Real d,
                                  MatrixX& local_matrix) {
  const int n_local = values.n_nodes() * dim;
  LocalMatrix<dim, n_nodes> penalty = LocalMatrix<dim, n_nodes>::Zero(n_local, n_local);
  for (int q = 0; q < values.n_points(); ++q) {
    // ε̇_V(φ_a e_i) = ∂_i φ_a: the flattened gradient is the divergence row.
    const Eigen::Map<const LocalVector<dim, n_nodes>> divergence(values.gradients(q).data(),
                                                                 n_local);
    penalty.template selfadjointView<Eigen::Lower>().rankUpdate(divergence,
                                                                values.JxW(q) / d); // (1/d) dx
  }
  penalty.template triangularView<Eigen::StrictlyUpper>() =
      penalty.transpose(); // symmetric: mirror once
  local_matrix += penalty;
}

} // namespace

template <int dim>
void add_volumetric_penalty(const fem::CellValues<dim>& values, Real d, MatrixX& local_matrix) {
  with_node_count<dim>(values.n_nodes(), [&](auto n_nodes) {
    add_volumetric_penalty_sized<dim, decltype(n_nodes)::value>(values, d, local_matrix);
  });
}

template void add_volumetric_penalty<2>(const fem::CellValues<2>&, Real, MatrixX&);
template void add_volumetric_penalty<3>(const fem::CellValues<3>&, Real, MatrixX&);

} // namespace formflow::assembly
