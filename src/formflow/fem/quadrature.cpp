// SPDX-License-Identifier: MIT
// Gauss–Legendre rules, tabulated in closed form up to five points, and the nodal
// (Gauss–Lobatto: trapezoid, Simpson) rules of Q1 and Q2 faces.
#include "formflow/fem/quadrature.hpp"

#include "formflow/core/error.hpp"

#include <cmath>

namespace formflow::fem {

void gauss_1d(int n, std::vector<Real>& points, std::vector<Real>& weights) {
  FF_ASSERT(n >= 1 && n <= max_gauss_points, "unsupported Gauss rule");
  switch (n) {
  case 1:
    points = {0.0};
    weights = {2.0};
    break;
  case 2: {
    const Real a = 1.0 / std::sqrt(3.0);
    points = {-a, a};
    weights = {1.0, 1.0};
    break;
  }
  case 3: {
    const Real a = std::sqrt(0.6);
    points = {-a, 0.0, a};
    weights = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    break;
  }
  case 4: {
    const Real a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
    const Real b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
    const Real wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
    points = {-b, -a, a, b};
    weights = {wb, wa, wa, wb};
    break;
  }
  default: {
    const Real a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const Real b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const Real wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
    const Real wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
    points = {-b, -a, 0.0, a, b};
    weights = {wb, wa, 128.0 / 225.0, wa, wb};
    break;
  }
  }
}

namespace {

template <int dim>
QuadratureRule<dim> tensor_rule(const std::vector<Real>& points_1d,
                                const std::vector<Real>& weights_1d) {
  const int n_per_direction = static_cast<int>(points_1d.size());
  int n_total = 1;
  for (int d = 0; d < dim; ++d) n_total *= n_per_direction;
  QuadratureRule<dim> rule;
  for (int q = 0; q < n_total; ++q) {
    Point<dim> point;
    Real weight = 1.0;
    int rest = q;
    for (int d = 0; d < dim; ++d) { // lexicographic, x fastest, like the nodes
      point[d] = points_1d[rest % n_per_direction];
      weight *= weights_1d[rest % n_per_direction];
      rest /= n_per_direction;
    }
    rule.points.push_back(point);
    rule.weights.push_back(weight);
  }
  return rule;
}

} // namespace

template <int dim> QuadratureRule<dim> gauss_rule(int n_per_direction) {
  std::vector<Real> points_1d, weights_1d;
  gauss_1d(n_per_direction, points_1d, weights_1d);
  return tensor_rule<dim>(points_1d, weights_1d);
}

template <int dim> QuadratureRule<dim> nodal_rule(int n_per_direction) {
  FF_ASSERT(n_per_direction == 2 || n_per_direction == 3, "nodal rules exist for Q1 and Q2 faces");
  if (n_per_direction == 2) return tensor_rule<dim>({-1.0, 1.0}, {1.0, 1.0});
  return tensor_rule<dim>({-1.0, 0.0, 1.0}, {1.0 / 3.0, 4.0 / 3.0, 1.0 / 3.0});
}

template QuadratureRule<1> nodal_rule<1>(int);
template QuadratureRule<2> nodal_rule<2>(int);
template QuadratureRule<3> nodal_rule<3>(int);
template QuadratureRule<1> gauss_rule<1>(int);
template QuadratureRule<2> gauss_rule<2>(int);
template QuadratureRule<3> gauss_rule<3>(int);

} // namespace formflow::fem
