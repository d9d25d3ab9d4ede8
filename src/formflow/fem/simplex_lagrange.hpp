// SPDX-License-Identifier: MIT
// Nodal shape functions P1, P2, P1b and P2+ on the unit triangle and tetrahedron.
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/fem/quadrature.hpp"

#include <vector>

namespace formflow::fem {

/// Reference simplex: triangle v0 = (0,0), v1 = (1,0), v2 = (0,1); tetrahedron
/// v0 = (0,0,0), v1 = (1,0,0), v2 = (0,1,0), v3 = (0,0,1). Barycentrics λ0 = 1 − Σ ξ,
/// λi = ξ_i. Local node numbering is VTK's: the vertices, then the edge midpoints
///
///   triangle            tetrahedron                 3 ζ
///   η                                             ,/|`\      edges
///   2                                           ,/  |  `\      4 (0,1)
///   |`\                                       ,7    '.   `9    5 (1,2)
///   |  `\                                   ,/       8     `\    6 (2,0)
///   5    `4                               ,/         |       `\  7 (0,3)
///   |      `\                            0--------6--'.--------2 η 8 (1,3)
///   0---3----1 ξ                          `\.         |      ,/    9 (2,3)
///                                            `\.      |    ,5
///   edges 3 (0,1), 4 (1,2), 5 (2,0)             `4.   '. ,/
///                                                  `\. |/
///                                                     `1
///                                                        `\ ξ
///
/// (the tetrahedron's is VTK_QUADRATIC_TETRA's order; Gmsh's tet10 swaps 8 and 9). With
/// `bubbles` (mesh::CellType): P1b is P1 and a node at the cell centroid (triangle node 3,
/// tetrahedron node 4); P2+ is P2, in 3D the four face centroids (node 10 + k at the centroid
/// of the face opposite vertex k), then the cell centroid (triangle node 6, tetrahedron 14).
///
/// Every basis is nodal, N_a(x_b) = δ_ab, for the space: P1b = span(P1, λ0λ1λ2[λ3]);
/// triangle P2+ = span(P2, λ0λ1λ2); tetrahedron P2+ = span(P2, the face bubbles λiλjλk,
/// λ0λ1λ2λ3). A nodal bubble basis (rather than P1/P2 plus a hierarchical bubble) keeps
/// every mesh node a point value, so interpolation, output and the isoparametric map treat
/// bubble nodes like any other node; on a straight-sided cell with its bubble nodes at the
/// centroids the isoparametric map Σ x_a N_a is the affine map, since the space contains P1.

/// Number of nodes of the layout (triangle 3, 6, 4, 7; tetrahedron 4, 10, 5, 15 for
/// P1, P2, P1b, P2+). Precondition order ∈ {1, 2}; dim 2 or 3.
template <int dim> int simplex_nodes(int order, bool bubbles);

/// Values (n_nodes) and reference gradients (dim × n_nodes) of the nodal shape functions
/// of the layout (order, bubbles) at reference point `xi`.
template <int dim>
void tabulate_simplex_shape(int order, bool bubbles, const Point<dim>& xi, VectorX& values,
                            Eigen::Matrix<Real, dim, Eigen::Dynamic>& gradients);

/// Reference second derivatives ∂²N_a/∂ξ_i∂ξ_j of the same shape functions at `xi`, one
/// dim × dim matrix per node.
template <int dim>
std::vector<Eigen::Matrix<Real, dim, dim>> tabulate_simplex_hessians(int order, bool bubbles,
                                                                     const Point<dim>& xi);

/// The reference coordinates of local node `local` of the layout (order, bubbles).
template <int dim> Point<dim> simplex_reference_node(int order, bool bubbles, int local);

/// Extrapolation from the points of a simplex rule to the nodes of the layout (order,
/// bubbles), the simplices' gauss_to_nodes: row a holds the weights of the point values
/// for node a of the least-squares fit of a complete polynomial of degree `order` (P1 or P2,
/// no bubbles) evaluated at node a. Shape (n_nodes, rule.size()). Precondition: the rule's
/// points are unisolvent for that polynomial space (at least dim + 1, resp.
/// (dim + 1)(dim + 2)/2 points, not all on one line/plane, resp. conic/quadric).
template <int dim>
MatrixX simplex_points_to_nodes(int order, bool bubbles, const QuadratureRule<dim>& rule);

} // namespace formflow::fem
