// SPDX-License-Identifier: MIT
// Which normal the contact penalty and the friction law use on Γ3: the face's
// own normal at Gauss points, or one normal per node, averaged over the faces
// that meet there (docs/validation.md, "Contact normals").
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/mesh/mesh.hpp"

#include <span>
#include <vector>

namespace formflow::assembly {

enum class ContactNormals {
  /// u_N = u·n_face at the face's Gauss points (the paper's discretisation).
  Faces,
  /// u_N = u·n_node at the face nodes (nodal quadrature), n_node the length-weighted
  /// mean of the normals of the faces sharing the node.
  Nodes,
};

struct ContactSettings {
  ContactNormals normals = ContactNormals::Faces;
  /// Nodes only: where the faces meeting at a node turn by more than this angle
  /// (degrees), the node is a real corner and each face keeps its own normal
  /// there, so the corner node cannot move (a dead-metal corner such as the
  /// square die's); below it the node slides along the averaged normal's tangent.
  Real corner_angle = 60.0;
};

/// The nodal contact normal at every point of the nodal face rule
/// (fem::nodal_rule, points = face nodes) of the Γ3 faces `contact_facets`
/// (indices into mesh.facets), face-major in the order given: a node's normal is
/// Σ_faces JxW_face(node) n_face(node), normalised, unless the faces there turn
/// by more than `corner_angle_degrees`, where each face's own normal is kept.
template <int dim>
std::vector<Point<dim>> nodal_contact_normals(const mesh::Mesh<dim>& mesh,
                                              std::span<const Index> contact_facets,
                                              Real corner_angle_degrees);

} // namespace formflow::assembly
