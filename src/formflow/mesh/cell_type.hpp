// SPDX-License-Identifier: MIT
// What a mesh's cells are: their reference shape (square/cube or simplex), their
// polynomial order and whether simplices carry bubble nodes.
#pragma once

#include <string_view>
#include <vector>

namespace formflow::mesh {

/// Reference shape of a cell: [-1, 1]^dim (quadrilateral, hexahedron) or the unit
/// simplex {ξ ≥ 0, Σ ξ ≤ 1} (triangle, tetrahedron).
enum class CellShape { Cube, Simplex };

/// The cells a case asks for (mesh.cell): the shape together with the dimension it
/// belongs to, so that a resolved case names what it ran.
enum class CellKind { Quadrilateral, Triangle, Hexahedron, Tetrahedron };

inline CellShape shape_of(CellKind kind) {
  return kind == CellKind::Triangle || kind == CellKind::Tetrahedron ? CellShape::Simplex
                                                                     : CellShape::Cube;
}
/// 2 for quadrilaterals and triangles, 3 for hexahedra and tetrahedra.
inline int dimension_of(CellKind kind) {
  return kind == CellKind::Quadrilateral || kind == CellKind::Triangle ? 2 : 3;
}
/// The kind of `shape` in dimension `dim`.
inline CellKind cell_kind(CellShape shape, int dim) {
  if (shape == CellShape::Simplex) return dim == 2 ? CellKind::Triangle : CellKind::Tetrahedron;
  return dim == 2 ? CellKind::Quadrilateral : CellKind::Hexahedron;
}

/// The node layout of a mesh's cells. Cubes: Q1 (2^dim nodes) or Q2 (3^dim nodes),
/// lexicographic (fem/lagrange.hpp). Simplices: P1 (vertices) or P2 (vertices, then edge
/// midpoints), with `bubbles` also P1b (P1 and a cell-centroid node) or P2+ (P2, the face
/// centroids in 3D, then the cell centroid); fem/simplex_lagrange.hpp draws the order.
struct CellType {
  CellShape shape = CellShape::Cube;
  int order = 1;        ///< 1 or 2
  bool bubbles = false; ///< simplices only: the bubble-enriched P1b / P2+ layouts

  bool is_simplex() const { return shape == CellShape::Simplex; }
  friend bool operator==(const CellType&, const CellType&) = default;
};

/// Nodes per cell of `type` in dimension dim (2 or 3).
template <int dim> int nodes_per_cell(const CellType& type);
/// Faces per cell: 2·dim for cubes, dim + 1 for simplices.
template <int dim> int faces_per_cell(const CellType& type);
/// Vertices per cell: 2^dim for cubes, dim + 1 for simplices.
template <int dim> int vertices_per_cell(const CellType& type);
/// Nodes per face (those face_local_nodes lists).
template <int dim> int nodes_per_face(const CellType& type);

/// Local node indices of face `local_face` of a cell of `type`.
/// Cubes: faces 2·axis + side, nodes lexicographic along the face (the order of a
/// (dim−1)-dimensional cube of the same order). Simplices: triangle face k is edge
/// (k, k+1 mod 3), its nodes in order along it [v_k, (midpoint), v_{k+1}] (the order of
/// the 1D Gauss–Lobatto points); tetrahedron face k is the triangle opposite vertex k,
/// nodes in triangle order (vertices, edge midpoints, face centroid with bubbles) with
/// its vertices as `simplex_face_vertices` lists them. A cell bubble is never on a face.
template <int dim> std::vector<int> face_local_nodes(const CellType& type, int local_face);

/// The vertices (local indices) of simplex face `local_face`, in the order the face's own
/// reference simplex takes them (its vertex 0, 1[, 2]); the outward normal follows the
/// right-hand rule in 3D.
template <int dim> std::vector<int> simplex_face_vertices(int local_face);

/// Local index of the P2 midpoint node of simplex edge (a, b), a ≠ b vertices (triangle
/// 3:(0,1) 4:(1,2) 5:(2,0); tetrahedron 4:(0,1) 5:(1,2) 6:(2,0) 7:(0,3) 8:(1,3) 9:(2,3)).
template <int dim> int simplex_edge_midpoint(int a, int b);

/// "quadrilateral", "triangle" (2D) or "hexahedron", "tetrahedron" (3D).
std::string_view cell_shape_name(CellShape shape, int dim);

} // namespace formflow::mesh
