// SPDX-License-Identifier: MIT
// The viscous a-form with the secant viscosity (SPEC §2, eq. 3.3).
#include "formflow/assembly/kernels/kernels.hpp"

namespace formflow::assembly {

// For basis functions φ_a e_i and φ_b e_j:
//   ε̇(φ_a e_i) : ε̇(φ_b e_j) = ½ (δ_ij ∇φ_a·∇φ_b + ∂_j φ_a ∂_i φ_b),
//   ė : ė = ε̇ : ε̇ − ⅓ ε̇_V ε̇_V with ε̇_V(φ_a e_i) = ∂_i φ_a.
template <int dim>
void add_viscous_term(const fem::CellValues<dim>& values, std::span<const Real> viscosity,
                      physics::ViscousStrain strain, MatrixX& local_matrix) {
  const int n = values.n_nodes();
  const Real volumetric_share = strain == physics::ViscousStrain::Deviatoric ? 1.0 / 3.0 : 0.0;
  for (int q = 0; q < values.n_points(); ++q) {
    const auto& grad = values.gradients(q);
    const Real factor = 2.0 / 3.0 * viscosity[q] * values.JxW(q);  // ⅔ ν dx
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const Real dot = 0.5 * grad.col(a).dot(grad.col(b));
        for (int i = 0; i < dim; ++i)
          for (int j = 0; j < dim; ++j) {
            Real term = 0.5 * grad(j, a) * grad(i, b) - volumetric_share * grad(i, a) * grad(j, b);
            if (i == j) term += dot;
            local_matrix(a * dim + i, b * dim + j) += factor * term;
          }
      }
  }
}

template void add_viscous_term<2>(const fem::CellValues<2>&, std::span<const Real>,
                                  physics::ViscousStrain, MatrixX&);
template void add_viscous_term<3>(const fem::CellValues<3>&, std::span<const Real>,
                                  physics::ViscousStrain, MatrixX&);

}  // namespace formflow::assembly
