// SPDX-License-Identifier: MIT
// Quadrature rules on the unit simplex: small symmetric rules, conical Gauss–Jacobi products.
#pragma once

#include "formflow/fem/quadrature.hpp"

namespace formflow::fem {

// Simplex rules reuse QuadratureRule<dim>, but their points live on the unit simplex
// {ξ ≥ 0, Σ ξ ≤ 1} (segment [0, 1], triangle, tetrahedron), not on [-1, 1]^dim, and their
// weights sum to its measure 1/dim! (1, 1/2, 1/6).

/// A rule on the unit simplex of dimension dim (1, 2, 3) exact for every polynomial of total
/// degree ≤ `degree` (any degree ≥ 0), with positive weights and points strictly inside.
/// Triangle: degree 0–1 the centroid (1 point), 2 the interior 3-point rule, 3–4 the 6-point
/// rule of degree 4, 5 the 7-point rule of degree 5. Tetrahedron: degree 0–1 the centroid,
/// 2 the 4-point rule. Segment: Gauss–Legendre. Above those, the conical (collapsed, Stroud)
/// product of n-point Gauss–Jacobi rules with 2n − 1 ≥ degree: n^dim points.
template <int dim> QuadratureRule<dim> simplex_rule(int degree);

/// The dim + 1 vertices of the unit simplex (in reference-vertex order: the origin, then
/// the unit vectors) with equal weights measure/(dim + 1). Exact for degree 1; integrating
/// a P1 face term with it lumps the term onto the face's vertices (contact at the nodes).
template <int dim> QuadratureRule<dim> simplex_vertex_rule();

/// A rule on the unit triangle with one point on each node of a P1, P2 or P2+ triangle, in
/// its node order (vertices, the midpoints of edges (0,1), (1,2), (2,0), then the centroid
/// with `centroid`), all weights positive, so that a face term integrated with it puts one
/// point on every face node of a tetrahedron (contact at the nodes). P1: the vertex rule
/// (degree 1). P2: the vertices 1/19 and midpoints 16/57 of the area, the diagonal of the P2
/// mass matrix scaled to sum to the area (the Hinton–Rock–Zienkiewicz lumping; degree 1 —
/// the degree-2 rule on these points has zero vertex weights and would leave the vertices
/// unconstrained). P2+: the 7-point rule of degree 3 (vertices 1/20, midpoints 2/15,
/// centroid 9/20).
QuadratureRule<2> triangle_nodal_rule(int order, bool centroid);

} // namespace formflow::fem
