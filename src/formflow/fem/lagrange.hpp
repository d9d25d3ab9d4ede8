// SPDX-License-Identifier: MIT
// Tensor-product Lagrange shape functions Q1 and Q2 on [-1, 1]^dim.
#pragma once

#include "formflow/core/types.hpp"

#include <string_view>
#include <vector>

namespace formflow::fem {

/// The velocity element (mesh.element). On quadrilaterals and hexahedra: Q1
/// (bilinear/trilinear, 2^dim nodes) or Q2 (biquadratic/triquadratic, 3^dim nodes). On
/// triangles and tetrahedra (fem/simplex_lagrange.hpp): P1b (the MINI element, P1 and a
/// cell bubble, paired with the continuous P1 pressure) or P2 (quadratic; with a
/// discontinuous pressure enriched by bubbles, P2+, fem/element_choice.hpp).
enum class ElementKind { Q1, Q2, P1b, P2 };

inline int element_order(ElementKind kind) {
  return kind == ElementKind::Q1 || kind == ElementKind::P1b ? 1 : 2;
}
inline bool is_simplex_element(ElementKind kind) {
  return kind == ElementKind::P1b || kind == ElementKind::P2;
}
inline std::string_view element_name(ElementKind kind) {
  switch (kind) {
  case ElementKind::Q1: return "Q1";
  case ElementKind::Q2: return "Q2";
  case ElementKind::P1b: return "P1b";
  case ElementKind::P2: return "P2";
  }
  return "?";
}

/// Local node numbering is lexicographic on the reference lattice, x fastest.
/// The 1D nodes are ξ = −1, +1 (Q1) and ξ = −1, 0, +1 (Q2):
///
///   Q1 (2D)      Q2 (2D)            η
///   2 --- 3      6 --- 7 --- 8      ^
///   |     |      |     |     |      |
///   |     |      3 --- 4 --- 5      +--> ξ
///   0 --- 1      0 --- 1 --- 2
///
/// In 3D the ζ = −1 layer comes first, then ζ = 0 (Q2), then ζ = +1.
/// VTK orders these cells differently; io/vtu.cpp maps between the two.

/// 1D node coordinate `i` of an element of `order` (0 ≤ i ≤ order).
inline Real lattice_coordinate(int order, int i) {
  return -1.0 + 2.0 * i / order;
}

/// Values (n_nodes) and reference gradients (dim × n_nodes) of the
/// tensor-product shape functions of `order` at reference point `xi`.
template <int dim>
void tabulate_shape(int order, const Point<dim>& xi, VectorX& values,
                    Eigen::Matrix<Real, dim, Eigen::Dynamic>& gradients);

/// Reference second derivatives ∂²N_a/∂ξ_i∂ξ_j of the same shape functions at `xi`, one
/// dim × dim matrix per node (the SUPG residual's diffusion term, assembly/heat_problem.cpp).
template <int dim>
std::vector<Eigen::Matrix<Real, dim, dim>> tabulate_hessians(int order, const Point<dim>& xi);

/// The reference coordinates of local node `local` of an element of `order`.
template <int dim> Point<dim> reference_node(int order, int local);

} // namespace formflow::fem

namespace formflow::fem {

/// Extrapolation from the n^dim Gauss points of a tensor rule to the nodes of
/// an element of `order`: row a holds the weights of the Gauss-point values
/// for node a (tensor product of 1D Lagrange polynomials through the Gauss
/// points). Shape (n_nodes, n_points^dim). One point per direction gives the
/// constant (cell mean) extrapolation.
template <int dim> MatrixX gauss_to_nodes(int order, int n_points_per_direction);

} // namespace formflow::fem
