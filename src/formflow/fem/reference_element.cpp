// SPDX-License-Identifier: MIT
// Shape functions and rules of any cell type, dispatched on mesh::CellType.
#include "formflow/fem/reference_element.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/fem/simplex_lagrange.hpp"
#include "formflow/fem/simplex_quadrature.hpp"

namespace formflow::fem {

template <int dim>
void tabulate_shape(const mesh::CellType& type, const Point<dim>& xi, VectorX& values,
                    Eigen::Matrix<Real, dim, Eigen::Dynamic>& gradients) {
  if (type.is_simplex())
    tabulate_simplex_shape<dim>(type.order, type.bubbles, xi, values, gradients);
  else
    tabulate_shape<dim>(type.order, xi, values, gradients);
}

template <int dim>
std::vector<Eigen::Matrix<Real, dim, dim>> tabulate_hessians(const mesh::CellType& type,
                                                             const Point<dim>& xi) {
  if (type.is_simplex()) return tabulate_simplex_hessians<dim>(type.order, type.bubbles, xi);
  return tabulate_hessians<dim>(type.order, xi);
}

template <int dim> Point<dim> reference_node(const mesh::CellType& type, int local) {
  if (type.is_simplex()) return simplex_reference_node<dim>(type.order, type.bubbles, local);
  return reference_node<dim>(type.order, local);
}

template <int dim> QuadratureRule<dim> full_rule(const mesh::CellType& type) {
  if (!type.is_simplex()) return gauss_rule<dim>(type.order + 1);
  // The highest polynomial degree of the shape functions: the bubble ∏λ has degree dim + 1.
  const int degree = type.bubbles ? dim + 1 : type.order;
  return simplex_rule<dim>(2 * (degree - 1) + 1);
}

template <int dim> QuadratureRule<dim - 1> face_rule(const mesh::CellType& type) {
  if constexpr (dim == 3)
    if (type.is_simplex()) // a face bubble (P2+) has degree 3 on the face: 2·3 covers its mass
      return simplex_rule<2>(type.bubbles && type.order == 2 ? 6 : 2 * type.order);
  return gauss_rule<dim - 1>(type.order + 1);
}

template <int dim> QuadratureRule<dim - 1> face_nodal_rule(const mesh::CellType& type) {
  if constexpr (dim == 3)
    if (type.is_simplex()) return triangle_nodal_rule(type.order, type.bubbles && type.order == 2);
  return nodal_rule<dim - 1>(type.order + 1);
}

template <int dim> QuadratureRule<dim> node_points(const mesh::CellType& type) {
  if (!type.is_simplex()) return nodal_rule<dim>(type.order + 1);
  QuadratureRule<dim> rule;
  const int n = mesh::nodes_per_cell<dim>(type);
  const Real measure = dim == 2 ? 0.5 : 1.0 / 6.0;
  for (int a = 0; a < n; ++a) {
    rule.points.push_back(reference_node<dim>(type, a));
    rule.weights.push_back(measure / n);
  }
  return rule;
}

template <int dim> QuadratureRule<dim> rule_of_points(const mesh::CellType& type, int n) {
  if (!type.is_simplex()) return gauss_rule<dim>(n);
  return simplex_rule<dim>(2 * n - 1);
}

#define FORMFLOW_INSTANTIATE(dim)                                                                  \
  template void tabulate_shape<dim>(const mesh::CellType&, const Point<dim>&, VectorX&,            \
                                    Eigen::Matrix<Real, dim, Eigen::Dynamic>&);                    \
  template std::vector<Eigen::Matrix<Real, dim, dim>> tabulate_hessians<dim>(                      \
      const mesh::CellType&, const Point<dim>&);                                                   \
  template Point<dim> reference_node<dim>(const mesh::CellType&, int);                             \
  template QuadratureRule<dim> full_rule<dim>(const mesh::CellType&);                              \
  template QuadratureRule<dim - 1> face_rule<dim>(const mesh::CellType&);                          \
  template QuadratureRule<dim - 1> face_nodal_rule<dim>(const mesh::CellType&);                    \
  template QuadratureRule<dim> node_points<dim>(const mesh::CellType&);                            \
  template QuadratureRule<dim> rule_of_points<dim>(const mesh::CellType&, int);
FORMFLOW_INSTANTIATE(2)
FORMFLOW_INSTANTIATE(3)
#undef FORMFLOW_INSTANTIATE

} // namespace formflow::fem
