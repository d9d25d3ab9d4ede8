// SPDX-License-Identifier: MIT
// The shape functions and quadrature rules of any cell type: tensor-product cells
// (fem/lagrange.hpp, fem/quadrature.hpp) or simplices (fem/simplex_lagrange.hpp,
// fem/simplex_quadrature.hpp), chosen by the mesh's mesh::CellType.
#pragma once

#include "formflow/fem/quadrature.hpp"
#include "formflow/mesh/cell_type.hpp"

#include <vector>

namespace formflow::fem {

/// Values (n_nodes) and reference gradients (dim × n_nodes) of the shape functions of
/// `type` at reference point `xi` (on [-1, 1]^dim or the unit simplex).
template <int dim>
void tabulate_shape(const mesh::CellType& type, const Point<dim>& xi, VectorX& values,
                    Eigen::Matrix<Real, dim, Eigen::Dynamic>& gradients);

/// Reference second derivatives of the same shape functions, one dim × dim matrix per node.
template <int dim>
std::vector<Eigen::Matrix<Real, dim, dim>> tabulate_hessians(const mesh::CellType& type,
                                                             const Point<dim>& xi);

/// The reference coordinates of local node `local` of `type`.
template <int dim> Point<dim> reference_node(const mesh::CellType& type, int local);

/// The cell's own rule for the a-form and every term integrated with it: Gauss with
/// order + 1 points per direction on cubes (exact for the Q-element's mass and stiffness on
/// affine cells); on simplices exact to degree 2(p − 1) + 1, p the highest degree of the
/// shape functions (P2: 2, P1b and P2+ triangles: 3, their tetrahedra: 4), so the
/// stiffness of an affine cell is exact also with axisymmetry's weight r.
template <int dim> QuadratureRule<dim> full_rule(const mesh::CellType& type);

/// Gauss points on a face, in the face's own reference coordinates: order + 1 per
/// direction on [-1, 1]^(dim−1) (a cube's face; a triangle's edge is [-1, 1] too), or on a
/// tetrahedron's face the unit triangle's rule of degree 2·order.
template <int dim> QuadratureRule<dim - 1> face_rule(const mesh::CellType& type);

/// The face rule whose points are the face's nodes, in mesh::face_local_nodes order
/// (Gauss–Lobatto: a face term integrated with it is lumped onto the nodes; a tetrahedron's
/// triangle face: fem/simplex_quadrature.hpp triangle_nodal_rule, positive weights).
template <int dim> QuadratureRule<dim - 1> face_nodal_rule(const mesh::CellType& type);

/// A "rule" whose points are the cell's nodes in local order (weights: the cell measure
/// shared equally; for checks at the nodes, not for integration).
template <int dim> QuadratureRule<dim> node_points(const mesh::CellType& type);

/// A rule exact for degree 2n − 1 in each variable on cubes (n^dim Gauss points) or of
/// total degree 2n − 1 on simplices: error norms and other integrals of a chosen accuracy.
template <int dim> QuadratureRule<dim> rule_of_points(const mesh::CellType& type, int n);

} // namespace formflow::fem
