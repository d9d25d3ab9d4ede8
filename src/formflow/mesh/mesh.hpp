// SPDX-License-Identifier: MIT
// Unstructured mesh of tensor-product cells (quadrilaterals, hexahedra) or simplices
// (triangles, tetrahedra) with labelled boundary facets.
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/mesh/cell_type.hpp"

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace formflow::mesh {

/// Boundary parts of SPEC §1. Physics refers to these labels, never to coordinates.
enum class BoundaryLabel {
  Rear,      ///< Γ1, the rear end (ram side)
  FreeEntry, ///< Γ2, free surface before the die
  Container, ///< Γ3, contact with the container wall
  Die,       ///< Γ3, contact with the die face
  FreeExit,  ///< Γ4, free surface after the die
  Front,     ///< Γ5, the front end
  Symmetry,  ///< Γ6, the symmetry plane
};
inline constexpr int n_boundary_labels = 7;

/// Lower-case label name as used in case files and outputs ("rear", "container", ...).
std::string_view label_name(BoundaryLabel label);
/// The label named `name` (the inverse of label_name), or std::nullopt.
std::optional<BoundaryLabel> label_from_name(std::string_view name);
/// True for the parts of the contact boundary Γ3.
inline bool is_contact(BoundaryLabel label) {
  return label == BoundaryLabel::Container || label == BoundaryLabel::Die;
}

/// One boundary facet: a face of a cell. Local faces of a tensor-product cell
/// are numbered 2·axis + side (side 0 at ξ_axis = −1, side 1 at ξ_axis = +1); those of
/// a simplex as mesh/cell_type.hpp says (triangle: edge (k, k+1); tetrahedron: opposite
/// vertex k).
struct BoundaryFacet {
  Index cell = 0;
  int local_face = 0;
  BoundaryLabel label = BoundaryLabel::Rear;
};

/// Mesh of Lagrange cells of polynomial order 1 or 2: tensor-product cells, nodes in
/// lexicographic order of the reference lattice, x fastest (fem/lagrange.hpp), or
/// simplices, nodes as fem/simplex_lagrange.hpp draws them.
template <int dim> struct Mesh {
  static constexpr int dimension = dim; ///< for code that receives a Mesh through std::visit
  int order = 1;                        ///< 1: Q1 / P1 (P1b), 2: Q2 / P2 (P2+)
  CellShape shape = CellShape::Cube;    ///< quadrilaterals/hexahedra or triangles/tetrahedra
  bool bubbles = false;                 ///< simplices: the bubble nodes of P1b / P2+
  /// Node coordinates, shape (dim, n_nodes).
  Eigen::Matrix<Real, dim, Eigen::Dynamic> nodes;
  /// Cell connectivity, shape (nodes_per_cell, n_cells), lexicographic order.
  Eigen::Matrix<Index, Eigen::Dynamic, Eigen::Dynamic> cells;
  std::vector<BoundaryFacet> facets;

  Index n_nodes() const { return static_cast<Index>(nodes.cols()); }
  Index n_cells() const { return static_cast<Index>(cells.cols()); }
  int nodes_per_cell() const { return static_cast<int>(cells.rows()); }
  /// Nodes along a cell edge of a tensor-product cell (order + 1).
  int nodes_per_side() const { return order + 1; }
  CellType cell_type() const { return {shape, order, bubbles}; }
  bool is_simplex() const { return shape == CellShape::Simplex; }
  /// Local nodes of face `local_face` (mesh::face_local_nodes of the cell type).
  std::vector<int> face_nodes(int local_face) const {
    return face_local_nodes<dim>(cell_type(), local_face);
  }
};

/// Lexicographic local node indices of face `local_face` of a tensor-product cell with
/// `n_side` nodes per direction, in lexicographic order along the face.
template <int dim> std::vector<int> face_local_nodes(int n_side, int local_face);

} // namespace formflow::mesh
