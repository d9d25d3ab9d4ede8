// SPDX-License-Identifier: MIT
// Triangles from a quadrilateral mesh: each cell cut along a diagonal, the Q2 lattice
// giving the P2 nodes, and the bubble nodes of P1b / P2+ added at the centroids.
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// The triangles of `quadrilaterals` (Q1 or Q2): cell c becomes cells 2c and 2c + 1,
/// cut along its diagonal from local vertex 0 to local vertex 3 (lexicographic: ξ = η = −1
/// to ξ = η = +1), so that both triangles are counter-clockwise where the quadrilateral is.
/// A Q2 cell's nine nodes are the two P2 triangles' nodes; its centre node, the midpoint
/// of the diagonal, is moved onto the straight diagonal (it belongs to this cell only), so
/// that a straight-sided quadrilateral gives straight-sided (affine) triangles. With
/// `bubbles`, one node per triangle is appended at the image of its reference centroid
/// (P1b: 4 nodes, P2+: 7 nodes per cell). Boundary facets keep their labels and move to
/// the triangle that owns their side. Every node a quadrilateral had is kept, in its place.
Mesh<2> split_into_triangles(const Mesh<2>& quadrilaterals, bool bubbles);

/// Appends one bubble node per simplex at the image of the reference cell centroid (and,
/// for P2 tetrahedra, one per face at the face centroid, shared by the two cells of an
/// interior face): the P1b / P2+ layout of mesh/cell_type.hpp. `simplices` has no bubbles.
template <int dim> Mesh<dim> with_bubble_nodes(const Mesh<dim>& simplices);

} // namespace formflow::mesh
