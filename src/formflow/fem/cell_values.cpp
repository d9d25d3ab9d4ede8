// SPDX-License-Identifier: MIT
// Isoparametric mapping of cells and faces.
#include "formflow/fem/cell_values.hpp"

#include "formflow/fem/lagrange.hpp"

#include <Eigen/LU> // determinant() and inverse() of the Jacobian

namespace formflow::fem {

template <int dim>
CellValues<dim>::CellValues(int order, const QuadratureRule<dim>& rule) : weights_(rule.weights) {
  const int n_q = rule.size();
  shape_.resize(n_q);
  reference_gradients_.resize(n_q);
  for (int q = 0; q < n_q; ++q)
    tabulate_shape<dim>(order, rule.points[q], shape_[q], reference_gradients_[q]);
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

template <int dim>
FacetValues<dim>::FacetValues(int order, const QuadratureRule<dim - 1>& face_rule)
    : order_(order), face_rule_(face_rule) {
  const int n_q = face_rule.size();
  shape_.resize(n_q);
  gradients_.resize(n_q);
  jxw_.assign(n_q, 0.0);
  normals_.assign(n_q, Point<dim>::Zero());
  points_.assign(n_q, Point<dim>::Zero());
}

template <int dim> void FacetValues<dim>::reinit(const Gradients& cell_nodes, int local_face) {
  const int axis = local_face / 2;
  const Real side = (local_face % 2 == 0) ? -1.0 : 1.0;
  Point<dim> reference_normal = Point<dim>::Zero();
  reference_normal[axis] = side;
  Gradients reference_gradients;
  for (int q = 0; q < n_points(); ++q) {
    // Embed the face point: the face coordinates fill the axes other than `axis`.
    Point<dim> xi;
    for (int d = 0, f = 0; d < dim; ++d) xi[d] = (d == axis) ? side : face_rule_.points[q][f++];
    tabulate_shape<dim>(order_, xi, shape_[q], reference_gradients);
    const Tensor2<dim> jacobian = cell_nodes * reference_gradients.transpose();
    const Tensor2<dim> inverse_transpose = jacobian.transpose().inverse();
    gradients_[q].noalias() = inverse_transpose * reference_gradients;
    // Nanson: n dA = det J · J⁻ᵀ N dA_ref.
    const Point<dim> scaled = jacobian.determinant() * inverse_transpose * reference_normal;
    const Real measure = scaled.norm();
    normals_[q] = scaled / measure;
    jxw_[q] = face_rule_.weights[q] * measure;
    points_[q].noalias() = cell_nodes * shape_[q];
  }
}

template class CellValues<2>;
template class CellValues<3>;
template class FacetValues<2>;
template class FacetValues<3>;

} // namespace formflow::fem
