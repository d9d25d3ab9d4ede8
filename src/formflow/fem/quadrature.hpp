// SPDX-License-Identifier: MIT
// Tensor-product Gauss–Legendre rules on the reference cell [-1, 1]^dim.
#pragma once

#include "formflow/core/types.hpp"

#include <vector>

namespace formflow::fem {

/// Points and weights on [-1, 1]^dim; weights sum to 2^dim.
template <int dim> struct QuadratureRule {
  std::vector<Point<dim>> points;
  std::vector<Real> weights;
  int size() const { return static_cast<int>(points.size()); }
};

/// Largest number of Gauss points per direction available.
inline constexpr int max_gauss_points = 5;

/// n^dim-point Gauss rule, exact for polynomials of degree 2n − 1 in each
/// variable. Precondition 1 ≤ n ≤ max_gauss_points.
template <int dim> QuadratureRule<dim> gauss_rule(int n_per_direction);

/// n^dim-point Gauss–Lobatto rule whose points are the nodes of a face of order
/// n − 1 (n = 2: trapezoid, n = 3: Simpson), in the same lexicographic order;
/// integrating with it lumps a face term onto the nodes. Precondition 2 ≤ n ≤ 3.
template <int dim> QuadratureRule<dim> nodal_rule(int n_per_direction);

/// 1D Gauss–Legendre points (ascending) and weights on [-1, 1].
void gauss_1d(int n, std::vector<Real>& points, std::vector<Real>& weights);

} // namespace formflow::fem
