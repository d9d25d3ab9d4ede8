// SPDX-License-Identifier: MIT
// Tensor-product Lagrange shape functions.
#include "formflow/fem/lagrange.hpp"

#include <array>

namespace formflow::fem {

namespace {

/// 1D Lagrange basis through the equispaced nodes of `order`: values and derivatives.
void basis_1d(int order, Real x, std::array<Real, 3>& value, std::array<Real, 3>& derivative) {
  if (order == 1) {
    value = {0.5 * (1 - x), 0.5 * (1 + x), 0};
    derivative = {-0.5, 0.5, 0};
  } else {
    value = {0.5 * x * (x - 1), (1 - x) * (1 + x), 0.5 * x * (x + 1)};
    derivative = {x - 0.5, -2 * x, x + 0.5};
  }
}

/// Second derivatives of the same 1D basis (constant: the basis is at most quadratic).
std::array<Real, 3> second_derivative_1d(int order) {
  return order == 1 ? std::array<Real, 3>{0, 0, 0} : std::array<Real, 3>{1, -2, 1};
}

} // namespace

template <int dim>
std::vector<Eigen::Matrix<Real, dim, dim>> tabulate_hessians(int order, const Point<dim>& xi) {
  const int n_side = order + 1;
  int n_nodes = 1;
  for (int d = 0; d < dim; ++d) n_nodes *= n_side;
  std::array<std::array<Real, 3>, dim> value_1d{}, derivative_1d{};
  for (int d = 0; d < dim; ++d) basis_1d(order, xi[d], value_1d[d], derivative_1d[d]);
  const std::array<Real, 3> second_1d = second_derivative_1d(order);
  std::vector<Eigen::Matrix<Real, dim, dim>> hessians(n_nodes);
  for (int local = 0; local < n_nodes; ++local) {
    std::array<int, dim> index{};
    int rest = local;
    for (int d = 0; d < dim; ++d) {
      index[d] = rest % n_side;
      rest /= n_side;
    }
    for (int g = 0; g < dim; ++g)
      for (int h = 0; h < dim; ++h) {
        Real partial = 1.0;
        for (int d = 0; d < dim; ++d) {
          const int derivatives = (d == g) + (d == h);
          partial *= derivatives == 0   ? value_1d[d][index[d]]
                     : derivatives == 1 ? derivative_1d[d][index[d]]
                                        : second_1d[index[d]];
        }
        hessians[local](g, h) = partial;
      }
  }
  return hessians;
}

template <int dim>
void tabulate_shape(int order, const Point<dim>& xi, VectorX& values,
                    Eigen::Matrix<Real, dim, Eigen::Dynamic>& gradients) {
  const int n_side = order + 1;
  int n_nodes = 1;
  for (int d = 0; d < dim; ++d) n_nodes *= n_side;
  std::array<std::array<Real, 3>, dim> value_1d{}, derivative_1d{};
  for (int d = 0; d < dim; ++d) basis_1d(order, xi[d], value_1d[d], derivative_1d[d]);

  values.resize(n_nodes);
  gradients.resize(dim, n_nodes);
  for (int local = 0; local < n_nodes; ++local) {
    std::array<int, dim> index{};
    int rest = local;
    for (int d = 0; d < dim; ++d) {
      index[d] = rest % n_side;
      rest /= n_side;
    }
    Real product = 1.0;
    for (int d = 0; d < dim; ++d) product *= value_1d[d][index[d]];
    values[local] = product;
    for (int g = 0; g < dim; ++g) {
      Real partial = 1.0;
      for (int d = 0; d < dim; ++d)
        partial *= (d == g) ? derivative_1d[d][index[d]] : value_1d[d][index[d]];
      gradients(g, local) = partial;
    }
  }
}

template <int dim> Point<dim> reference_node(int order, int local) {
  Point<dim> xi;
  int rest = local;
  for (int d = 0; d < dim; ++d) {
    xi[d] = lattice_coordinate(order, rest % (order + 1));
    rest /= order + 1;
  }
  return xi;
}

template void tabulate_shape<2>(int, const Point<2>&, VectorX&,
                                Eigen::Matrix<Real, 2, Eigen::Dynamic>&);
template void tabulate_shape<3>(int, const Point<3>&, VectorX&,
                                Eigen::Matrix<Real, 3, Eigen::Dynamic>&);
template std::vector<Eigen::Matrix<Real, 2, 2>> tabulate_hessians<2>(int, const Point<2>&);
template std::vector<Eigen::Matrix<Real, 3, 3>> tabulate_hessians<3>(int, const Point<3>&);
template Point<2> reference_node<2>(int, int);
template Point<3> reference_node<3>(int, int);

} // namespace formflow::fem

#include "formflow/fem/quadrature.hpp"

namespace formflow::fem {

template <int dim> MatrixX gauss_to_nodes(int order, int n_points_per_direction) {
  std::vector<Real> gauss, unused;
  gauss_1d(n_points_per_direction, gauss, unused);
  const int n_side = order + 1, m = n_points_per_direction;
  // lagrange_1d(i, k): k-th Lagrange polynomial through the Gauss points at node coordinate i.
  MatrixX lagrange_1d(n_side, m);
  for (int i = 0; i < n_side; ++i)
    for (int k = 0; k < m; ++k) {
      Real value = 1.0;
      for (int l = 0; l < m; ++l)
        if (l != k) value *= (lattice_coordinate(order, i) - gauss[l]) / (gauss[k] - gauss[l]);
      lagrange_1d(i, k) = value;
    }
  int n_nodes = 1, n_q = 1;
  for (int d = 0; d < dim; ++d) {
    n_nodes *= n_side;
    n_q *= m;
  }
  MatrixX result(n_nodes, n_q);
  for (int a = 0; a < n_nodes; ++a)
    for (int q = 0; q < n_q; ++q) {
      Real value = 1.0;
      int node_rest = a, point_rest = q;
      for (int d = 0; d < dim; ++d) {
        value *= lagrange_1d(node_rest % n_side, point_rest % m);
        node_rest /= n_side;
        point_rest /= m;
      }
      result(a, q) = value;
    }
  return result;
}

template MatrixX gauss_to_nodes<1>(int, int);
template MatrixX gauss_to_nodes<2>(int, int);
template MatrixX gauss_to_nodes<3>(int, int);

} // namespace formflow::fem
