// SPDX-License-Identifier: MIT
// Shape values, physical gradients and JxW of one cell at a quadrature rule.
#pragma once

#include "formflow/fem/quadrature.hpp"
#include "formflow/mesh/cell_type.hpp"

#include <vector>

namespace formflow::fem {

template <int dim> class CellValuesCache;
template <int dim> class FacetValuesCache;

/// Tabulates the reference shape functions once per rule; `reinit` maps them
/// to one physical cell (isoparametric map x(ξ) = Σ_a X_a N_a(ξ)).
template <int dim> class CellValues {
public:
  using Gradients = Eigen::Matrix<Real, dim, Eigen::Dynamic>;

  CellValues(const mesh::CellType& type, const QuadratureRule<dim>& rule);
  /// A tensor-product cell (Q1, Q2) of `order`.
  CellValues(int order, const QuadratureRule<dim>& rule)
      : CellValues(mesh::CellType{mesh::CellShape::Cube, order, false}, rule) {}

  /// Maps to the cell with node coordinates `cell_nodes` (dim × n_nodes, in the cell
  /// type's local order).
  /// Returns false when the Jacobian is not positive at some point (inverted cell).
  bool reinit(const Gradients& cell_nodes);

  int n_points() const { return static_cast<int>(weights_.size()); }
  int n_nodes() const { return n_nodes_; }
  /// N_a(ξ_q), length n_nodes.
  const VectorX& shape(int q) const { return shape_[q]; }
  /// ∂N_a/∂x_i at point q after reinit, shape (dim, n_nodes).
  const Gradients& gradients(int q) const { return gradients_[q]; }
  /// Quadrature weight times Jacobian determinant at point q after reinit.
  Real JxW(int q) const { return jxw_[q]; }
  /// Physical coordinates of point q after reinit.
  const Point<dim>& point(int q) const { return points_[q]; }
  /// Axisymmetry (y = r): multiplies each JxW by r, the measure per radian. Call after reinit.
  void weight_by_radius() {
    for (int q = 0; q < n_points(); ++q) jxw_[q] *= points_[q][1];
  }

private:
  friend class CellValuesCache<dim>; // stores and restores the mapped values (fem/values_cache.hpp)
  int n_nodes_ = 0;
  std::vector<Real> weights_;
  std::vector<VectorX> shape_;
  std::vector<Gradients> reference_gradients_;
  std::vector<Gradients> gradients_;
  std::vector<Real> jxw_;
  std::vector<Point<dim>> points_;
};

/// Where a face's reference point s lands in its cell's reference coordinates,
/// ξ = origin + span · s, with the face's outward unit reference normal.
template <int dim> struct FaceEmbedding {
  Point<dim> origin;
  Eigen::Matrix<Real, dim, dim - 1> span;
  Point<dim> normal;
  Real measure_scale = 1.0; ///< reference face measure per unit of the face rule's measure
};

/// Shape values, JxW (surface measure) and outward unit normals on one face
/// of a cell; `face_rule` is a (dim−1)-dimensional rule placed on the face: on
/// [-1, 1]^(dim−1) for a cube's face and a triangle's edge, on the unit triangle for a
/// tetrahedron's face (fem::face_rule).
template <int dim> class FacetValues {
public:
  using Gradients = Eigen::Matrix<Real, dim, Eigen::Dynamic>;

  FacetValues(const mesh::CellType& type, const QuadratureRule<dim - 1>& face_rule);
  /// A face of a tensor-product cell (Q1, Q2) of `order`.
  FacetValues(int order, const QuadratureRule<dim - 1>& face_rule)
      : FacetValues(mesh::CellType{mesh::CellShape::Cube, order, false}, face_rule) {}

  /// Maps to face `local_face` of the cell with `cell_nodes` (cubes: 2·axis + side;
  /// simplices: mesh/cell_type.hpp).
  void reinit(const Gradients& cell_nodes, int local_face);

  int n_points() const { return static_cast<int>(face_rule_.weights.size()); }
  int n_nodes() const { return static_cast<int>(shape_.empty() ? 0 : shape_[0].size()); }
  /// Cell shape functions N_a at face point q (length n_nodes of the cell).
  const VectorX& shape(int q) const { return shape_[q]; }
  /// Cell shape gradients ∂N_a/∂x_i at face point q, shape (dim, n_nodes): the strain
  /// rate at a surface point (the Tresca threshold's flow stress there).
  const Gradients& gradients(int q) const { return gradients_[q]; }
  /// Surface element: weight times |det J · J⁻ᵀ N_ref| (Nanson's formula).
  Real JxW(int q) const { return jxw_[q]; }
  const Point<dim>& normal(int q) const { return normals_[q]; }
  const Point<dim>& point(int q) const { return points_[q]; }
  /// Axisymmetry (y = r): multiplies each JxW by r, the measure per radian. Call after reinit.
  void weight_by_radius() {
    for (int q = 0; q < n_points(); ++q) jxw_[q] *= points_[q][1];
  }
  /// Replaces the face normal at point q (nodal contact normals, assembly/contact_normals.hpp)
  /// until the next reinit. `normal` must be a unit vector.
  void set_normal(int q, const Point<dim>& normal) { normals_[q] = normal; }

private:
  friend class FacetValuesCache<dim>; // stores and restores the mapped values
                                      // (fem/values_cache.hpp)
  mesh::CellType type_;
  QuadratureRule<dim - 1> face_rule_;
  /// Each local face's place in the reference cell, made once (reinit runs in loops).
  std::vector<FaceEmbedding<dim>> embeddings_;
  std::vector<VectorX> shape_;
  std::vector<Gradients> gradients_;
  std::vector<Real> jxw_;
  std::vector<Point<dim>> normals_;
  std::vector<Point<dim>> points_;
};

} // namespace formflow::fem
