// SPDX-License-Identifier: MIT
// Consistent-tangent correction of the viscous a-form (Newton, SPEC §2 eq. 3.3).
#include "formflow/assembly/kernels/fixed_size.hpp"
#include "formflow/assembly/kernels/tangent_kernels.hpp"

namespace formflow::assembly {

namespace {

// ė(u):ε̇(φ_a e_i) = Σ_j ė_ij ∂_j φ_a (ė symmetric, and ė:I = 0 removes the
// volumetric part of ε̇(v)), so the row over local dofs is ė·∇φ_a per node: the
// dim × n matrix ė ∇φ read column by column.
template <int dim, int n_nodes>
void add_viscous_tangent_sized(const fem::CellValues<dim>& values,
                               std::span<const Tensor3> deviators, std::span<const Tensor3> duals,
                               std::span<const Real> a, std::span<const Real> b,
                               MatrixX& local_matrix) {
  using NodeGradients = Eigen::Matrix<Real, dim, n_nodes>;
  const int n = values.n_nodes(), size = n * dim;
  LocalMatrix<dim, n_nodes> tangent = LocalMatrix<dim, n_nodes>::Zero(size, size);
  NodeGradients g(dim, n), h(dim, n);
  for (int q = 0; q < values.n_points(); ++q) {
    if (a[q] == 0.0 && b[q] == 0.0) continue;
    const Eigen::Map<const NodeGradients> grad(values.gradients(q).data(), dim, n);
    g.noalias() = deviators[q].template topLeftCorner<dim, dim>() * grad;
    h.noalias() = duals[q].template topLeftCorner<dim, dim>() * grad;
    const Eigen::Map<const LocalVector<dim, n_nodes>> g_row(g.data(), size), h_row(h.data(), size);
    const Real jxw = values.JxW(q);
    // a g⊗g + b sym(h⊗g) = ½ (v⊗g + g⊗v) with v = a g + b h: one symmetric rank-2
    // update of the lower triangle, mirrored once at the end.
    const LocalVector<dim, n_nodes> v = a[q] * g_row + b[q] * h_row;
    tangent.template selfadjointView<Eigen::Lower>().rankUpdate(v, g_row, 0.5 * jxw); // dx
  }
  tangent.template triangularView<Eigen::StrictlyUpper>() = tangent.transpose();
  local_matrix += tangent;
}

} // namespace

template <int dim>
void add_viscous_tangent(const fem::CellValues<dim>& values, std::span<const Tensor3> deviators,
                         std::span<const Tensor3> duals, std::span<const Real> a,
                         std::span<const Real> b, MatrixX& local_matrix) {
  with_node_count<dim>(values.n_nodes(), [&](auto n_nodes) {
    add_viscous_tangent_sized<dim, decltype(n_nodes)::value>(values, deviators, duals, a, b,
                                                             local_matrix);
  });
}

// Axisymmetry adds the hoop slot: ė:ε̇(φ_a e_r) gains ė_θθ φ_a/r (values r-weighted).
void add_viscous_tangent_axisymmetric(const fem::CellValues<2>& values,
                                      std::span<const Tensor3> deviators,
                                      std::span<const Tensor3> duals, std::span<const Real> a,
                                      std::span<const Real> b, MatrixX& local_matrix) {
  const int n = values.n_nodes();
  CellVector g(n * 2), h(n * 2);
  for (int q = 0; q < values.n_points(); ++q) {
    if (a[q] == 0.0 && b[q] == 0.0) continue;
    const Tensor2<2> dev = deviators[q].topLeftCorner<2, 2>();
    const Tensor2<2> dual = duals[q].topLeftCorner<2, 2>();
    const auto& grad = values.gradients(q);
    const Real radius = values.point(q)[1];
    for (int node = 0; node < n; ++node) {
      g.segment<2>(node * 2) = dev * grad.col(node);
      h.segment<2>(node * 2) = dual * grad.col(node);
      g[node * 2 + 1] += deviators[q](2, 2) * values.shape(q)[node] / radius;
      h[node * 2 + 1] += duals[q](2, 2) * values.shape(q)[node] / radius;
    }
    const Real jxw = values.JxW(q);
    local_matrix.noalias() += (a[q] * jxw) * g * g.transpose();
    local_matrix.noalias() += (0.5 * b[q] * jxw) * (h * g.transpose() + g * h.transpose());
  }
}

template void add_viscous_tangent<2>(const fem::CellValues<2>&, std::span<const Tensor3>,
                                     std::span<const Tensor3>, std::span<const Real>,
                                     std::span<const Real>, MatrixX&);
template void add_viscous_tangent<3>(const fem::CellValues<3>&, std::span<const Tensor3>,
                                     std::span<const Tensor3>, std::span<const Real>,
                                     std::span<const Real>, MatrixX&);

} // namespace formflow::assembly
