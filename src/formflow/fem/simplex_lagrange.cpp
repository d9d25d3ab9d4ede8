// SPDX-License-Identifier: MIT
// Simplex shape functions, built generically: primal functions (Lagrange P1/P2 and bubbles,
// polynomials in the barycentrics) made nodal by the inverse of their Vandermonde matrix.
#include "formflow/fem/simplex_lagrange.hpp"

#include "formflow/core/error.hpp"

#include <Eigen/LU>
#include <Eigen/QR>

#include <array>
#include <utility>

namespace formflow::fem {

namespace {

/// The largest layout: the P2+ tetrahedron (10 P2 nodes, 4 face and 1 cell centroid).
constexpr int max_simplex_layout_nodes = 15;

/// c · Π_i λ_i^{p_i}, a monomial in the barycentrics (p_i ≤ 2).
struct BarycentricTerm {
  Real coefficient = 0;
  std::array<int, 4> power{}; ///< λ0..λ3; λ3 unused in 2D
};

/// One primal function: a sum of barycentric monomials.
using PrimalFunction = std::vector<BarycentricTerm>;

/// A node layout: its reference nodes, its primal functions φ_b and the inverse of their
/// Vandermonde matrix V_ab = φ_b(x_a), so that the nodal basis is N_a = Σ_b φ_b (V⁻¹)_ba.
template <int dim> struct SimplexLayout {
  std::vector<Point<dim>> nodes;
  std::vector<PrimalFunction> primal;
  MatrixX inverse_vandermonde;
  bool primal_is_nodal = false; ///< P1 and P2: V is the identity, V⁻¹ is skipped
};

/// The reference point with barycentric coordinates `lambda` (its Cartesian coordinates
/// are λ1..λdim).
template <int dim> Point<dim> barycentric_point(const std::array<Real, dim + 1>& lambda) {
  Point<dim> point;
  for (int d = 0; d < dim; ++d) point[d] = lambda[d + 1];
  return point;
}

/// x^p for a small p; 1 for p ≤ 0 (the derivative factor p or p(p − 1) is then 0 anyway).
Real barycentric_power(Real x, int p) {
  Real result = 1;
  for (int k = 0; k < p; ++k) result *= x;
  return result;
}

/// Value, λ-gradient and λ-Hessian of φ = Σ c Π λ_i^{p_i}, the λ_i taken as independent.
template <int dim>
void evaluate_barycentric(const PrimalFunction& function, const std::array<Real, dim + 1>& lambda,
                          Real& value, Eigen::Matrix<Real, dim + 1, 1>& gradient,
                          Eigen::Matrix<Real, dim + 1, dim + 1>* hessian) {
  constexpr int n = dim + 1;
  value = 0;
  gradient.setZero();
  if (hessian) hessian->setZero();
  for (const BarycentricTerm& term : function) {
    // product_without(i, j): c times the product over the λ_k other than i and j.
    auto product_without = [&](int i, int j) {
      Real product = term.coefficient;
      for (int k = 0; k < n; ++k)
        if (k != i && k != j) product *= barycentric_power(lambda[k], term.power[k]);
      return product;
    };
    value += product_without(-1, -1);
    for (int i = 0; i < n; ++i) {
      const int p = term.power[i];
      if (p == 0) continue;
      gradient[i] += p * barycentric_power(lambda[i], p - 1) * product_without(i, i);
      if (!hessian) continue;
      if (p >= 2)
        (*hessian)(i, i) +=
            p * (p - 1) * barycentric_power(lambda[i], p - 2) * product_without(i, i);
      for (int j = 0; j < n; ++j) {
        const int q = term.power[j];
        if (j == i || q == 0) continue;
        (*hessian)(i, j) += p * q * barycentric_power(lambda[i], p - 1) *
                            barycentric_power(lambda[j], q - 1) * product_without(i, j);
      }
    }
  }
}

/// ∂λ/∂ξ, (dim + 1) × dim: λ0 = 1 − Σ ξ gives the row −1, λi = ξ_i the unit rows.
template <int dim> Eigen::Matrix<Real, dim + 1, dim> barycentric_jacobian() {
  Eigen::Matrix<Real, dim + 1, dim> jacobian;
  jacobian.row(0).setConstant(-1);
  jacobian.template bottomRows<dim>().setIdentity();
  return jacobian;
}

template <int dim> std::array<Real, dim + 1> barycentrics_of(const Point<dim>& xi) {
  std::array<Real, dim + 1> lambda{};
  lambda[0] = 1 - xi.sum();
  for (int d = 0; d < dim; ++d) lambda[d + 1] = xi[d];
  return lambda;
}

/// The edges of the P2 layout in VTK order (fem/simplex_lagrange.hpp draws them).
template <int dim> std::vector<std::pair<int, int>> layout_edges() {
  if constexpr (dim == 2)
    return {{0, 1}, {1, 2}, {2, 0}};
  else
    return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
}

/// The product of the λ_i over `members`, scaled to 1 at their common centroid
/// (λ_i = 1/|members|): the bubble of the face or cell they span.
PrimalFunction layout_bubble(const std::vector<int>& members) {
  BarycentricTerm term;
  const int m = static_cast<int>(members.size());
  term.coefficient = barycentric_power(m, m); // 1 / Π (1/m) = m^m: 27 for a triangle, 256 a tet
  for (int i : members) term.power[i] = 1;
  return {term};
}

template <int dim> SimplexLayout<dim> build_simplex_layout(int order, bool bubbles) {
  constexpr int n_vertices = dim + 1;
  SimplexLayout<dim> layout;
  auto add_node = [&](const std::array<Real, dim + 1>& lambda, PrimalFunction function) {
    layout.nodes.push_back(barycentric_point<dim>(lambda));
    layout.primal.push_back(std::move(function));
  };
  for (int i = 0; i < n_vertices; ++i) {
    std::array<Real, dim + 1> lambda{};
    lambda[i] = 1;
    BarycentricTerm linear{1, {}};
    linear.power[i] = 1;
    if (order == 1) {
      add_node(lambda, {linear});
    } else { // λ(2λ − 1): 1 at the vertex, 0 at the other vertices and at the midpoints
      BarycentricTerm square{2, {}};
      square.power[i] = 2;
      add_node(lambda, {square, {-1, linear.power}});
    }
  }
  if (order == 2)
    for (const auto& [i, j] : layout_edges<dim>()) {
      std::array<Real, dim + 1> lambda{};
      lambda[i] = lambda[j] = 0.5;
      add_node(lambda, layout_bubble({i, j})); // 4 λi λj, the P2 edge function
    }
  if (bubbles) {
    if (dim == 3 && order == 2)
      for (int k = 0; k < n_vertices; ++k) { // the face opposite vertex k
        std::array<Real, dim + 1> lambda{};
        std::vector<int> members;
        for (int i = 0; i < n_vertices; ++i)
          if (i != k) {
            lambda[i] = 1.0 / 3;
            members.push_back(i);
          }
        add_node(lambda, layout_bubble(members));
      }
    std::array<Real, dim + 1> lambda{};
    std::vector<int> members;
    for (int i = 0; i < n_vertices; ++i) {
      lambda[i] = 1.0 / n_vertices;
      members.push_back(i);
    }
    add_node(lambda, layout_bubble(members));
  }

  const int n = static_cast<int>(layout.nodes.size());
  MatrixX vandermonde(n, n);
  for (int a = 0; a < n; ++a) {
    const auto lambda = barycentrics_of<dim>(layout.nodes[a]);
    Eigen::Matrix<Real, dim + 1, 1> unused;
    for (int b = 0; b < n; ++b)
      evaluate_barycentric<dim>(layout.primal[b], lambda, vandermonde(a, b), unused, nullptr);
  }
  // P1 and P2 Lagrange functions are nodal already (V = I up to round-off in the node
  // coordinates 1/2); the bubble layouts are not: their P1/P2 functions do not vanish at
  // the centroids, and the inverse removes that.
  layout.primal_is_nodal = !bubbles;
  FF_ASSERT(!layout.primal_is_nodal || vandermonde.isIdentity(1e-14),
            "the P1/P2 Lagrange functions are nodal");
  const Eigen::FullPivLU<MatrixX> lu(vandermonde);
  FF_ASSERT(lu.isInvertible(), "the primal functions are unisolvent at the nodes");
  layout.inverse_vandermonde = lu.inverse();
  return layout;
}

/// The layout (order, bubbles), built once per dimension on first use: C++ initialises a
/// function-local static thread-safely, and the tables are only read afterwards.
template <int dim> const SimplexLayout<dim>& simplex_layout(int order, bool bubbles) {
  static_assert(dim == 2 || dim == 3, "simplex elements are triangles and tetrahedra");
  FF_ASSERT(order == 1 || order == 2, "simplex elements are P1 or P2 (with or without bubbles)");
  static const std::array<SimplexLayout<dim>, 4> layouts = {
      build_simplex_layout<dim>(1, false), build_simplex_layout<dim>(1, true),
      build_simplex_layout<dim>(2, false), build_simplex_layout<dim>(2, true)};
  return layouts[2 * (order - 1) + (bubbles ? 1 : 0)];
}

using PrimalValues = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, max_simplex_layout_nodes, 1>;
template <int dim>
using PrimalGradients = Eigen::Matrix<Real, dim, Eigen::Dynamic, 0, dim, max_simplex_layout_nodes>;

/// The primal functions of `layout` at `xi`: values, ξ-gradients and (if asked) ξ-Hessians,
/// by the chain rule through λ(ξ): ∇_ξ φ = Jᵀ ∇_λ φ, H_ξ φ = Jᵀ H_λ φ J.
template <int dim>
void evaluate_primal(const SimplexLayout<dim>& layout, const Point<dim>& xi, PrimalValues& values,
                     PrimalGradients<dim>& gradients,
                     std::vector<Eigen::Matrix<Real, dim, dim>>* hessians) {
  const int n = static_cast<int>(layout.primal.size());
  const auto lambda = barycentrics_of<dim>(xi);
  const Eigen::Matrix<Real, dim + 1, dim> jacobian = barycentric_jacobian<dim>();
  values.resize(n);
  gradients.resize(dim, n);
  if (hessians) hessians->resize(n);
  Eigen::Matrix<Real, dim + 1, 1> gradient_lambda;
  Eigen::Matrix<Real, dim + 1, dim + 1> hessian_lambda;
  for (int b = 0; b < n; ++b) {
    evaluate_barycentric<dim>(layout.primal[b], lambda, values[b], gradient_lambda,
                              hessians ? &hessian_lambda : nullptr);
    gradients.col(b) = jacobian.transpose() * gradient_lambda;
    if (hessians) (*hessians)[b] = jacobian.transpose() * hessian_lambda * jacobian;
  }
}

} // namespace

template <int dim> int simplex_nodes(int order, bool bubbles) {
  return static_cast<int>(simplex_layout<dim>(order, bubbles).nodes.size());
}

template <int dim> Point<dim> simplex_reference_node(int order, bool bubbles, int local) {
  const SimplexLayout<dim>& layout = simplex_layout<dim>(order, bubbles);
  FF_ASSERT(local >= 0 && local < static_cast<int>(layout.nodes.size()), "a node of the layout");
  return layout.nodes[local];
}

template <int dim>
void tabulate_simplex_shape(int order, bool bubbles, const Point<dim>& xi, VectorX& values,
                            Eigen::Matrix<Real, dim, Eigen::Dynamic>& gradients) {
  const SimplexLayout<dim>& layout = simplex_layout<dim>(order, bubbles);
  PrimalValues primal_values;
  PrimalGradients<dim> primal_gradients;
  evaluate_primal<dim>(layout, xi, primal_values, primal_gradients, nullptr);
  if (layout.primal_is_nodal) {
    values = primal_values;
    gradients = primal_gradients;
  } else { // N_a = Σ_b φ_b (V⁻¹)_ba
    values = layout.inverse_vandermonde.transpose() * primal_values;
    gradients = primal_gradients * layout.inverse_vandermonde;
  }
}

template <int dim>
std::vector<Eigen::Matrix<Real, dim, dim>> tabulate_simplex_hessians(int order, bool bubbles,
                                                                     const Point<dim>& xi) {
  const SimplexLayout<dim>& layout = simplex_layout<dim>(order, bubbles);
  PrimalValues primal_values;
  PrimalGradients<dim> primal_gradients;
  std::vector<Eigen::Matrix<Real, dim, dim>> primal_hessians;
  evaluate_primal<dim>(layout, xi, primal_values, primal_gradients, &primal_hessians);
  if (layout.primal_is_nodal) return primal_hessians;
  const int n = static_cast<int>(primal_hessians.size());
  std::vector<Eigen::Matrix<Real, dim, dim>> hessians(n, Eigen::Matrix<Real, dim, dim>::Zero());
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      hessians[a] += layout.inverse_vandermonde(b, a) * primal_hessians[b];
  return hessians;
}

template <int dim>
MatrixX simplex_points_to_nodes(int order, bool bubbles, const QuadratureRule<dim>& rule) {
  // The fitted space is P_order, spanned by the (nodal) primal functions of the plain layout.
  const SimplexLayout<dim>& space = simplex_layout<dim>(order, false);
  const SimplexLayout<dim>& target = simplex_layout<dim>(order, bubbles);
  const int m = static_cast<int>(space.primal.size());
  FF_ASSERT(rule.size() >= m, "at least as many points as the fitted polynomial space's dimension");
  PrimalValues values;
  PrimalGradients<dim> unused;
  MatrixX at_points(rule.size(), m), at_nodes(target.nodes.size(), m);
  for (int q = 0; q < rule.size(); ++q) {
    evaluate_primal<dim>(space, rule.points[q], values, unused, nullptr);
    at_points.row(q) = values.transpose();
  }
  for (int a = 0; a < static_cast<int>(target.nodes.size()); ++a) {
    evaluate_primal<dim>(space, target.nodes[a], values, unused, nullptr);
    at_nodes.row(a) = values.transpose();
  }
  // Least squares through a pivoted QR: the pseudo-inverse of at_points, column by column
  // of the identity. A pivot below 1e-10 of the largest means the points (nearly) lie on a
  // zero set of some polynomial of the space: not unisolvent, the fit is not determined.
  Eigen::ColPivHouseholderQR<MatrixX> qr(at_points);
  qr.setThreshold(1e-10);
  FF_ASSERT(qr.rank() == m, "the rule's points are unisolvent for the fitted polynomials");
  const MatrixX pseudo_inverse = qr.solve(MatrixX::Identity(rule.size(), rule.size()));
  return at_nodes * pseudo_inverse;
}

template int simplex_nodes<2>(int, bool);
template int simplex_nodes<3>(int, bool);
template Point<2> simplex_reference_node<2>(int, bool, int);
template Point<3> simplex_reference_node<3>(int, bool, int);
template void tabulate_simplex_shape<2>(int, bool, const Point<2>&, VectorX&,
                                        Eigen::Matrix<Real, 2, Eigen::Dynamic>&);
template void tabulate_simplex_shape<3>(int, bool, const Point<3>&, VectorX&,
                                        Eigen::Matrix<Real, 3, Eigen::Dynamic>&);
template std::vector<Eigen::Matrix<Real, 2, 2>> tabulate_simplex_hessians<2>(int, bool,
                                                                             const Point<2>&);
template std::vector<Eigen::Matrix<Real, 3, 3>> tabulate_simplex_hessians<3>(int, bool,
                                                                             const Point<3>&);
template MatrixX simplex_points_to_nodes<2>(int, bool, const QuadratureRule<2>&);
template MatrixX simplex_points_to_nodes<3>(int, bool, const QuadratureRule<3>&);

} // namespace formflow::fem
