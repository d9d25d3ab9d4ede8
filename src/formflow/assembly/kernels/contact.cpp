// SPDX-License-Identifier: MIT
// Normal contact penalty on Γ3 (SPEC §2, eq. 3.8): σ_N = −u_N/d_N.
#include "formflow/assembly/kernels/kernels.hpp"

namespace formflow::assembly {

template <int dim>
void add_contact_penalty(const fem::FacetValues<dim>& values, Real d_n, MatrixX& local_matrix) {
  const int n = static_cast<int>(values.shape(0).size());
  CellVector normal_row(n * dim);
  for (int q = 0; q < values.n_points(); ++q) {
    // u_N of the basis function φ_a e_i is φ_a n_i.
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i)
        normal_row[a * dim + i] = values.shape(q)[a] * values.normal(q)[i];
    local_matrix.noalias() +=
        (values.JxW(q) / d_n) * normal_row * normal_row.transpose(); // (1/d_N) dΓ
  }
}

template void add_contact_penalty<2>(const fem::FacetValues<2>&, Real, MatrixX&);
template void add_contact_penalty<3>(const fem::FacetValues<3>&, Real, MatrixX&);

} // namespace formflow::assembly
