// SPDX-License-Identifier: MIT
// Secant form of the regularised nonlocal Coulomb friction (SPEC §3, eq. 5.3).
#include "formflow/assembly/kernels/kernels.hpp"

namespace formflow::assembly {

template <int dim>
void add_friction_term(const fem::FacetValues<dim>& values, std::span<const Real> weight,
                       MatrixX& local_matrix) {
  const int n = static_cast<int>(values.shape(0).size());
  for (int q = 0; q < values.n_points(); ++q) {
    if (weight[q] == 0.0) continue;
    const auto& phi = values.shape(q);
    const Point<dim>& normal = values.normal(q);
    // u_T·v_T = u·(I − n⊗n)·v: the tangential projector between the components.
    const Tensor2<dim> projector = Tensor2<dim>::Identity() - normal * normal.transpose();
    const Real factor = weight[q] * values.JxW(q); // κ dΓ
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        local_matrix.template block<dim, dim>(a * dim, b * dim) +=
            factor * phi[a] * phi[b] * projector;
  }
}

template void add_friction_term<2>(const fem::FacetValues<2>&, std::span<const Real>, MatrixX&);
template void add_friction_term<3>(const fem::FacetValues<3>&, std::span<const Real>, MatrixX&);

} // namespace formflow::assembly
