// SPDX-License-Identifier: MIT
// Nodal (averaged) normals of the contact boundary Γ3.
//
// Why: with one normal per face, a node shared by two faces of different
// normals carries two independent constraints u·n₁ = u·n₂ = 0 and cannot move
// (a one-element dead zone at the container/die and die/land junctions), and a
// curved Q2 face imposes u·n = 0 at three Gauss points with three different
// normals for its two new nodes (over-constraint). With one normal per node and
// the penalty evaluated at the nodes, each Γ3 node carries exactly one normal
// constraint.
#include "formflow/assembly/contact_normals.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/cell_values.hpp"
#include "formflow/fem/reference_element.hpp"

#include <cmath>
#include <numbers>
#include <unordered_map>

namespace formflow::assembly {

template <int dim>
std::vector<Point<dim>> nodal_contact_normals(const mesh::Mesh<dim>& mesh,
                                              std::span<const Index> contact_facets,
                                              Real corner_angle_degrees) {
  const fem::QuadratureRule<dim - 1> rule = fem::face_nodal_rule<dim>(mesh.cell_type());
  const int n_q = rule.size();
  fem::FacetValues<dim> values(mesh.cell_type(), rule);
  typename fem::FacetValues<dim>::Gradients coordinates(dim, mesh.nodes_per_cell());

  // Face normals and the node of each point; length-weighted sums per node.
  std::vector<Point<dim>> face_normal(contact_facets.size() * n_q);
  std::vector<Index> node_of(face_normal.size());
  std::unordered_map<Index, Point<dim>> sum;
  std::unordered_map<Index, std::vector<std::size_t>> points_at;
  for (std::size_t p = 0; p < contact_facets.size(); ++p) {
    const mesh::BoundaryFacet& facet = mesh.facets[contact_facets[p]];
    for (int a = 0; a < mesh.nodes_per_cell(); ++a)
      coordinates.col(a) = mesh.nodes.col(mesh.cells(a, facet.cell));
    values.reinit(coordinates, facet.local_face);
    const std::vector<int> face_nodes = mesh.face_nodes(facet.local_face);
    FF_ASSERT(static_cast<int>(face_nodes.size()) == n_q, "one nodal-rule point per face node");
    for (int q = 0; q < n_q; ++q) {
      const std::size_t k = p * n_q + q;
      const Index node = mesh.cells(face_nodes[q], facet.cell);
      FF_ASSERT((values.point(q) - mesh.nodes.col(node)).norm() <=
                    1e-9 * (1.0 + mesh.nodes.col(node).norm()),
                "nodal-rule points in face-node order");
      face_normal[k] = values.normal(q);
      node_of[k] = node;
      auto [entry, inserted] = sum.try_emplace(node, Point<dim>::Zero());
      entry->second += values.JxW(q) * values.normal(q);
      points_at[node].push_back(k);
    }
  }

  // A real corner: two faces at the node whose normals differ by more than the angle.
  const Real cos_corner = std::cos(corner_angle_degrees * std::numbers::pi / 180.0);
  std::vector<Point<dim>> normals(face_normal.size());
  for (std::size_t k = 0; k < normals.size(); ++k) {
    const std::vector<std::size_t>& others = points_at[node_of[k]];
    bool corner = false;
    for (std::size_t i = 0; i < others.size() && !corner; ++i)
      for (std::size_t j = i + 1; j < others.size() && !corner; ++j)
        corner = face_normal[others[i]].dot(face_normal[others[j]]) < cos_corner;
    const Point<dim>& mean = sum[node_of[k]];
    normals[k] = corner || mean.norm() == 0.0 ? face_normal[k] : Point<dim>(mean.normalized());
  }
  return normals;
}

template std::vector<Point<2>> nodal_contact_normals<2>(const mesh::Mesh<2>&,
                                                        std::span<const Index>, Real);
template std::vector<Point<3>> nodal_contact_normals<3>(const mesh::Mesh<3>&,
                                                        std::span<const Index>, Real);

} // namespace formflow::assembly
