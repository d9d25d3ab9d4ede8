// SPDX-License-Identifier: MIT
// Isoparametric mapping of cells and faces.
#include "formflow/fem/cell_values.hpp"

#include "formflow/fem/reference_element.hpp"
#include "formflow/mesh/cell_type.hpp"

#include <Eigen/Geometry> // cross(): a tetrahedron face's area vector
#include <Eigen/LU>       // determinant() and inverse() of the Jacobian

namespace formflow::fem {

template <int dim>
CellValues<dim>::CellValues(const mesh::CellType& type, const QuadratureRule<dim>& rule)
    : weights_(rule.weights) {
  const int n_q = rule.size();
  shape_.resize(n_q);
  reference_gradients_.resize(n_q);
  for (int q = 0; q < n_q; ++q)
    tabulate_shape<dim>(type, rule.points[q], shape_[q], reference_gradients_[q]);
  n_nodes_ = static_cast<int>(shape_.front().size());
  gradients_.assign(n_q, Gradients(dim, n_nodes_));
  jxw_.assign(n_q, 0.0);
  points_.assign(n_q, Point<dim>::Zero());
}

template <int dim> bool CellValues<dim>::reinit(const Gradients& cell_nodes) {
  bool valid = true;
  for (int q = 0; q < n_points(); ++q) {
    // J_ij = ∂x_i/∂ξ_j = Σ_a X_ia ∂N_a/∂ξ_j
    const Tensor2<dim> jacobian = cell_nodes * reference_gradients_[q].transpose();
    const Real det = jacobian.determinant();
    valid = valid && det > 0;
    gradients_[q].noalias() = jacobian.transpose().inverse() * reference_gradients_[q];
    jxw_[q] = weights_[q] * det;
    points_[q].noalias() = cell_nodes * shape_[q];
  }
  return valid;
}

namespace {

template <int dim> FaceEmbedding<dim> face_embedding(const mesh::CellType& type, int local_face) {
  FaceEmbedding<dim> face;
  if (!type.is_simplex()) {
    // The face coordinates fill the axes other than `axis`, in order.
    const int axis = local_face / 2;
    const Real side = (local_face % 2 == 0) ? -1.0 : 1.0;
    face.origin.setZero();
    face.origin[axis] = side;
    face.span.setZero();
    for (int d = 0, f = 0; d < dim; ++d)
      if (d != axis) face.span(d, f++) = 1.0;
    face.normal.setZero();
    face.normal[axis] = side;
    return face;
  }
  const std::vector<int> vertices = mesh::simplex_face_vertices<dim>(local_face);
  std::vector<Point<dim>> corner;
  for (int v : vertices)
    corner.push_back(reference_node<dim>(mesh::CellType{type.shape, 1, false}, v));
  if constexpr (dim == 2) {
    // The edge's rule is on [-1, 1]: ξ = (c0 + c1)/2 + s (c1 − c0)/2.
    const Point<2> tangent = corner[1] - corner[0];
    face.origin = 0.5 * (corner[0] + corner[1]);
    face.span.col(0) = 0.5 * tangent;
    face.normal = Point<2>(tangent.y(), -tangent.x()).normalized(); // counter-clockwise cell
    face.measure_scale = 0.5 * tangent.norm();
  } else {
    // The face's rule is on the unit triangle: ξ = c0 + s1 (c1 − c0) + s2 (c2 − c0).
    face.origin = corner[0];
    face.span.col(0) = corner[1] - corner[0];
    face.span.col(1) = corner[2] - corner[0];
    const Point<3> area = face.span.col(0).cross(face.span.col(1));
    face.normal = area.normalized(); // mesh::simplex_face_vertices orders them outwards
    face.measure_scale = area.norm();
  }
  return face;
}

} // namespace

template <int dim>
FacetValues<dim>::FacetValues(const mesh::CellType& type, const QuadratureRule<dim - 1>& face_rule)
    : type_(type), face_rule_(face_rule) {
  for (int face = 0; face < mesh::faces_per_cell<dim>(type); ++face)
    embeddings_.push_back(face_embedding<dim>(type, face));
  const int n_q = face_rule.size();
  shape_.resize(n_q);
  gradients_.resize(n_q);
  jxw_.assign(n_q, 0.0);
  normals_.assign(n_q, Point<dim>::Zero());
  points_.assign(n_q, Point<dim>::Zero());
}

template <int dim> void FacetValues<dim>::reinit(const Gradients& cell_nodes, int local_face) {
  const FaceEmbedding<dim>& face = embeddings_[local_face];
  Gradients reference_gradients;
  for (int q = 0; q < n_points(); ++q) {
    const Point<dim> xi = face.origin + face.span * face_rule_.points[q];
    tabulate_shape<dim>(type_, xi, shape_[q], reference_gradients);
    const Tensor2<dim> jacobian = cell_nodes * reference_gradients.transpose();
    const Tensor2<dim> inverse_transpose = jacobian.transpose().inverse();
    gradients_[q].noalias() = inverse_transpose * reference_gradients;
    // Nanson: n dA = det J · J⁻ᵀ N dA_ref.
    const Point<dim> scaled = jacobian.determinant() * inverse_transpose * face.normal;
    const Real measure = scaled.norm();
    normals_[q] = scaled / measure;
    jxw_[q] = face_rule_.weights[q] * face.measure_scale * measure;
    points_[q].noalias() = cell_nodes * shape_[q];
  }
}

template class CellValues<2>;
template class CellValues<3>;
template class FacetValues<2>;
template class FacetValues<3>;

} // namespace formflow::fem
