// SPDX-License-Identifier: MIT
// The optimised kernels (symmetric rank updates, fixed sizes for Q1/Q2 in 2D and
// Q1 in 3D, dynamic for the Q2 hexahedron) against their definitions written as
// plain loops over node pairs and components, on distorted cells, with a local
// matrix that already holds values (the kernels add).
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/tangent_kernels.hpp"

#include "formflow/fem/lagrange.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <vector>

namespace formflow::testing {
namespace {

// Entries are sums of ≤ 27 products of O(1) gradients: 1e-13 of the matrix
// norm is round-off with margin, and far below any wrong term.
constexpr double reference_kernel_roundoff = 1e-13;

/// A distorted cell of `order`: each reference node moved by a smooth O(0.1) field.
template <int dim> typename fem::CellValues<dim>::Gradients distorted_cell(int order) {
  int n = 1;
  for (int d = 0; d < dim; ++d) n *= order + 1;
  typename fem::CellValues<dim>::Gradients nodes(dim, n);
  for (int a = 0; a < n; ++a) {
    const Point<dim> xi = fem::reference_node<dim>(order, a);
    for (int i = 0; i < dim; ++i)
      nodes(i, a) = (1.0 + 0.2 * i) * xi[i] + 0.08 * std::sin(1.7 * xi.sum() + i) +
                    0.05 * xi[(i + 1) % dim] * xi[i];
  }
  return nodes;
}

/// A symmetric 3×3 tensor, trace free when `deviatoric`, zero out of plane in 2D.
template <int dim> Tensor3 tensor(double seed, bool deviatoric) {
  Tensor3 t = Tensor3::Zero();
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j <= i; ++j) t(i, j) = t(j, i) = std::cos(seed + 3.0 * i + 1.3 * j);
  if (deviatoric) t -= t.trace() / 3.0 * Tensor3::Identity();
  return t;
}

MatrixX prefilled(int size) {
  MatrixX m(size, size);
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) m(r, c) = 0.01 * (r + 1) * (c + 1); // symmetric
  return m;
}

struct Case {
  int dim, order;
};
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.dim << "D Q" << c.order;
}

template <int dim> void check_viscous(int order, physics::ViscousStrain strain) {
  const fem::QuadratureRule<dim> rule = fem::gauss_rule<dim>(order + 1);
  fem::CellValues<dim> values(order, rule);
  ASSERT_TRUE(values.reinit(distorted_cell<dim>(order)));
  const int n = values.n_nodes(), size = n * dim;
  std::vector<Real> viscosity(rule.size());
  for (int q = 0; q < rule.size(); ++q) viscosity[q] = 1.0 + 0.5 * std::sin(q);
  const Real share = strain == physics::ViscousStrain::Deviatoric ? 1.0 / 3.0 : 0.0;
  MatrixX reference = prefilled(size);
  for (int q = 0; q < rule.size(); ++q) {
    const auto& g = values.gradients(q);
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i)
        for (int b = 0; b < n; ++b)
          for (int j = 0; j < dim; ++j) {
            // ε̇(φ_a e_i):ε̇(φ_b e_j) − share ε̇_V ε̇_V
            Real term = 0.5 * g(j, a) * g(i, b) - share * g(i, a) * g(j, b);
            if (i == j) term += 0.5 * g.col(a).dot(g.col(b));
            reference(a * dim + i, b * dim + j) += 2.0 / 3.0 * viscosity[q] * values.JxW(q) * term;
          }
  }
  MatrixX k = prefilled(size);
  assembly::add_viscous_term<dim>(values, viscosity, strain, k);
  EXPECT_TRUE(
      approx((k - reference).norm(), 0.0, 0.0, reference_kernel_roundoff * reference.norm()));
}

template <int dim> void check_volumetric(int order, int n_points) {
  const fem::QuadratureRule<dim> rule = fem::gauss_rule<dim>(n_points);
  fem::CellValues<dim> values(order, rule);
  ASSERT_TRUE(values.reinit(distorted_cell<dim>(order)));
  const int n = values.n_nodes(), size = n * dim;
  const Real d = 1e-3;
  MatrixX reference = prefilled(size);
  for (int q = 0; q < rule.size(); ++q)
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i)
        for (int b = 0; b < n; ++b)
          for (int j = 0; j < dim; ++j)
            reference(a * dim + i, b * dim + j) +=
                values.JxW(q) / d * values.gradients(q)(i, a) * values.gradients(q)(j, b);
  MatrixX k = prefilled(size);
  assembly::add_volumetric_penalty<dim>(values, d, k);
  EXPECT_TRUE(
      approx((k - reference).norm(), 0.0, 0.0, reference_kernel_roundoff * reference.norm()));
}

template <int dim> void check_tangent(int order) {
  const fem::QuadratureRule<dim> rule = fem::gauss_rule<dim>(order + 1);
  fem::CellValues<dim> values(order, rule);
  ASSERT_TRUE(values.reinit(distorted_cell<dim>(order)));
  const int n = values.n_nodes(), size = n * dim;
  std::vector<Tensor3> deviators, duals;
  std::vector<Real> a(rule.size()), b(rule.size());
  for (int q = 0; q < rule.size(); ++q) {
    deviators.push_back(tensor<dim>(0.3 * q, true));
    duals.push_back(tensor<dim>(2.0 + 0.7 * q, true));
    a[q] = 0.2 + 0.1 * q;
    b[q] = q == 1 ? 0.0 : -0.4 + 0.05 * q; // a point with b = 0 too
  }
  a[0] = b[0] = 0.0; // and one the kernel skips
  MatrixX reference = prefilled(size);
  for (int q = 0; q < rule.size(); ++q) {
    // g_ai = (ė ∇φ_a)_i, h_ai = (w ∇φ_a)_i; a g⊗g + b ½(h⊗g + g⊗h)
    const MatrixX g = deviators[q].template topLeftCorner<dim, dim>() * values.gradients(q);
    const MatrixX h = duals[q].template topLeftCorner<dim, dim>() * values.gradients(q);
    for (int p = 0; p < n; ++p)
      for (int i = 0; i < dim; ++i)
        for (int r = 0; r < n; ++r)
          for (int j = 0; j < dim; ++j)
            reference(p * dim + i, r * dim + j) +=
                values.JxW(q) *
                (a[q] * g(i, p) * g(j, r) + 0.5 * b[q] * (h(i, p) * g(j, r) + g(i, p) * h(j, r)));
  }
  MatrixX k = prefilled(size);
  assembly::add_viscous_tangent<dim>(values, deviators, duals, a, b, k);
  EXPECT_TRUE(
      approx((k - reference).norm(), 0.0, 0.0, reference_kernel_roundoff * reference.norm()));
}

class KernelReference : public ::testing::TestWithParam<Case> {};

TEST_P(KernelReference, ViscousTermMatchesItsDefinition) {
  for (const auto strain : {physics::ViscousStrain::Full, physics::ViscousStrain::Deviatoric}) {
    if (GetParam().dim == 2)
      check_viscous<2>(GetParam().order, strain);
    else
      check_viscous<3>(GetParam().order, strain);
  }
}

TEST_P(KernelReference, VolumetricPenaltyMatchesItsDefinition) {
  for (const int n_points : {1, 2, 3}) {
    if (GetParam().dim == 2)
      check_volumetric<2>(GetParam().order, n_points);
    else
      check_volumetric<3>(GetParam().order, n_points);
  }
}

TEST_P(KernelReference, ViscousTangentMatchesItsDefinition) {
  if (GetParam().dim == 2)
    check_tangent<2>(GetParam().order);
  else
    check_tangent<3>(GetParam().order);
}

INSTANTIATE_TEST_SUITE_P(Assembly, KernelReference,
                         ::testing::Values(Case{2, 1}, Case{2, 2}, Case{3, 1}, Case{3, 2}));

} // namespace
} // namespace formflow::testing
