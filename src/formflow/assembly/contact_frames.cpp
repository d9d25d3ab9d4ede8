// SPDX-License-Identifier: MIT
// The Γ3 nodes' free velocity dofs in their nodal normal–tangent frame.
#include "formflow/assembly/contact_frames.hpp"

#include "formflow/fem/dof_map.hpp"

#include <map>

namespace formflow::assembly {

namespace {

/// An orthonormal basis of R^k (k = normal.size() ≥ 2) whose first column is
/// normal/|normal|: Gram–Schmidt of the coordinate axes against it, leaving out the
/// axis closest to it, so every residual norm stays ≥ 1/√3 (no cancellation).
MatrixX basis_with_first_column(const VectorX& normal) {
  const Index k = normal.size();
  MatrixX basis(k, k);
  basis.col(0) = normal.normalized();
  Index closest = 0;
  basis.col(0).cwiseAbs().maxCoeff(&closest);
  Index column = 1;
  for (Index axis = 0; axis < k; ++axis) {
    if (axis == closest) continue;
    VectorX direction = VectorX::Unit(k, axis);
    for (Index previous = 0; previous < column; ++previous)
      direction -= basis.col(previous).dot(direction) * basis.col(previous);
    basis.col(column++) = direction.normalized();
  }
  return basis;
}

} // namespace

template <int dim>
std::map<Index, Point<dim>> contact_node_normals(const Discretisation<dim>& discretisation) {
  const mesh::Mesh<dim>& mesh = discretisation.mesh();
  const std::vector<Index>& facets = discretisation.contact_facets();
  const std::vector<Point<dim>> normals =
      nodal_contact_normals<dim>(mesh, facets, discretisation.settings().contact.corner_angle);
  // The node of each Γ3 point (face-major, face-node order: nodal_contact_normals').
  std::map<Index, Point<dim>> normal_sum;
  std::size_t point = 0;
  for (const Index facet_index : facets) {
    const mesh::BoundaryFacet& facet = mesh.facets[facet_index];
    for (const int local : mesh.face_nodes(facet.local_face)) {
      auto [entry, inserted] =
          normal_sum.try_emplace(mesh.cells(local, facet.cell), Point<dim>::Zero());
      entry->second += normals[point++];
    }
  }
  return normal_sum;
}

template <int dim>
std::vector<LocalFrame> contact_frames(const Discretisation<dim>& discretisation) {
  std::vector<LocalFrame> frames;
  // Ordered by node: the frames come out by node.
  const std::map<Index, Point<dim>> normal_sum = contact_node_normals(discretisation);
  const ScatterPlan& plan = discretisation.plan();
  for (const auto& [node, sum] : normal_sum) {
    LocalFrame frame;
    std::vector<Real> free_part;
    for (int component = 0; component < dim; ++component) {
      const Index row = plan.free_index(fem::dof_of<dim>(node, component));
      if (row < 0) continue;
      frame.rows.push_back(row);
      free_part.push_back(sum[component]);
    }
    const VectorX normal =
        Eigen::Map<const VectorX>(free_part.data(), static_cast<Index>(free_part.size()));
    if ((normal.array() != 0.0).count() < 2) continue; // already one dof (or none)
    frame.basis = basis_with_first_column(normal);
    frames.push_back(std::move(frame));
  }
  return frames;
}

template std::map<Index, Point<2>> contact_node_normals<2>(const Discretisation<2>&);
template std::map<Index, Point<3>> contact_node_normals<3>(const Discretisation<3>&);
template std::vector<LocalFrame> contact_frames<2>(const Discretisation<2>&);
template std::vector<LocalFrame> contact_frames<3>(const Discretisation<3>&);

} // namespace formflow::assembly
