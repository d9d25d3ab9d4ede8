// SPDX-License-Identifier: MIT
// Consistent-tangent correction of the regularised friction term (eq. 3.15), τ_f fixed.
#include "formflow/assembly/kernels/tangent_kernels.hpp"

namespace formflow::assembly {

template <int dim>
void add_friction_tangent(const fem::FacetValues<dim>& values, std::span<const Point<dim>> slip,
                          std::span<const Point<dim>> dual_slip, std::span<const Real> coefficient,
                          MatrixX& local_matrix) {
  const int n = static_cast<int>(values.shape(0).size());
  for (int q = 0; q < values.n_points(); ++q) {
    if (coefficient[q] == 0.0) continue;
    const auto& phi = values.shape(q);
    // u_T and λ are tangential, so u_T·v_T = u_T·v: no projector needed.
    const Tensor2<dim> outer =
        0.5 * (dual_slip[q] * slip[q].transpose() + slip[q] * dual_slip[q].transpose());
    const Real factor = -coefficient[q] * values.JxW(q); // −τ_f/s³ dΓ
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        local_matrix.template block<dim, dim>(a * dim, b * dim) += factor * phi[a] * phi[b] * outer;
  }
}

template void add_friction_tangent<2>(const fem::FacetValues<2>&, std::span<const Point<2>>,
                                      std::span<const Point<2>>, std::span<const Real>, MatrixX&);
template void add_friction_tangent<3>(const fem::FacetValues<3>&, std::span<const Point<3>>,
                                      std::span<const Point<3>>, std::span<const Real>, MatrixX&);

} // namespace formflow::assembly
