// SPDX-License-Identifier: MIT
// The viscous a-form with the secant viscosity (SPEC §2, eq. 3.3).
#include "formflow/assembly/kernels/fixed_size.hpp"
#include "formflow/assembly/kernels/kernels.hpp"

namespace formflow::assembly {

namespace {

// For basis functions φ_a e_i and φ_b e_j:
//   ε̇(φ_a e_i) : ε̇(φ_b e_j) = ½ (δ_ij ∇φ_a·∇φ_b + ∂_j φ_a ∂_i φ_b),
//   ė : ė = ε̇ : ε̇ − ⅓ ε̇_V ε̇_V with ε̇_V(φ_a e_i) = ∂_i φ_a.
// Every product here is an entry of P = Σ_q ⅔ ν JxW d_q d_qᵀ, d_q the flattened
// gradient (d_q[a·dim + i] = ∂_i φ_a): ∂_j φ_a ∂_i φ_b is P(a·dim + j, b·dim + i) and
// ∇φ_a·∇φ_b is Σ_k P(a·dim + k, b·dim + k). One rank-one update per point instead
// of dim² scalar products per node pair.
template <int dim, int n_nodes>
void add_viscous_term_sized(const fem::CellValues<dim>& values, std::span<const Real> viscosity,
                            Real volumetric_share, MatrixX& local_matrix) {
  const int n = n_nodes == Eigen::Dynamic ? values.n_nodes() : n_nodes, size = n * dim;
  LocalMatrix<dim, n_nodes> products = LocalMatrix<dim, n_nodes>::Zero(size, size);
  for (int q = 0; q < values.n_points(); ++q) {
    const Eigen::Map<const LocalVector<dim, n_nodes>> flat(values.gradients(q).data(), size);
    // P is symmetric: update its lower triangle only, then mirror it once.
    products.template selfadjointView<Eigen::Lower>().rankUpdate(flat, 2.0 / 3.0 * viscosity[q] *
                                                                           values.JxW(q)); // ⅔ ν dx
  }
  products.template triangularView<Eigen::StrictlyUpper>() = products.transpose();
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      Real dot = 0.0;
      for (int k = 0; k < dim; ++k) dot += products(a * dim + k, b * dim + k);
      for (int j = 0; j < dim; ++j)
        for (int i = 0; i < dim; ++i) {
          Real term = 0.5 * products(a * dim + j, b * dim + i) -
                      volumetric_share * products(a * dim + i, b * dim + j);
          if (i == j) term += 0.5 * dot;
          local_matrix(a * dim + i, b * dim + j) += term;
        }
    }
}

} // namespace

template <int dim>
void add_viscous_term(const fem::CellValues<dim>& values, std::span<const Real> viscosity,
                      physics::ViscousStrain strain, MatrixX& local_matrix) {
  const Real volumetric_share = strain == physics::ViscousStrain::Deviatoric ? 1.0 / 3.0 : 0.0;
  with_node_count<dim>(values.n_nodes(), [&](auto n_nodes) {
    add_viscous_term_sized<dim, decltype(n_nodes)::value>(values, viscosity, volumetric_share,
                                                          local_matrix);
  });
}

template void add_viscous_term<2>(const fem::CellValues<2>&, std::span<const Real>,
                                  physics::ViscousStrain, MatrixX&);
template void add_viscous_term<3>(const fem::CellValues<3>&, std::span<const Real>,
                                  physics::ViscousStrain, MatrixX&);

} // namespace formflow::assembly
