// SPDX-License-Identifier: MIT
// Unstructured mesh of tensor-product cells (quadrilaterals, hexahedra) with
// labelled boundary facets.
#pragma once

#include "formflow/core/types.hpp"

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
/// are numbered 2·axis + side (side 0 at ξ_axis = −1, side 1 at ξ_axis = +1).
struct BoundaryFacet {
  Index cell = 0;
  int local_face = 0;
  BoundaryLabel label = BoundaryLabel::Rear;
};

/// Mesh of tensor-product Lagrange cells of polynomial order 1 or 2.
/// Cell nodes are stored in lexicographic order of the reference lattice,
/// x fastest (see fem/lagrange.hpp for the drawing).
template <int dim> struct Mesh {
  static constexpr int dimension = dim; ///< for code that receives a Mesh through std::visit
  int order = 1; ///< 1: Q1 (2^dim nodes per cell), 2: Q2 (3^dim nodes per cell)
  /// Node coordinates, shape (dim, n_nodes).
  Eigen::Matrix<Real, dim, Eigen::Dynamic> nodes;
  /// Cell connectivity, shape (nodes_per_cell, n_cells), lexicographic order.
  Eigen::Matrix<Index, Eigen::Dynamic, Eigen::Dynamic> cells;
  std::vector<BoundaryFacet> facets;

  Index n_nodes() const { return static_cast<Index>(nodes.cols()); }
  Index n_cells() const { return static_cast<Index>(cells.cols()); }
  int nodes_per_cell() const { return static_cast<int>(cells.rows()); }
  int nodes_per_side() const { return order + 1; }
};

/// Lexicographic local node indices of face `local_face` of a cell with
/// `n_side` nodes per direction, in lexicographic order along the face.
template <int dim> std::vector<int> face_local_nodes(int n_side, int local_face);

} // namespace formflow::mesh
