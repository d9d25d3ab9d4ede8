// SPDX-License-Identifier: MIT
// A symmetry plane of a solid mesh as a plane mesh, for the field pictures of a 3D run.
#pragma once

#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"

#include <vector>

namespace formflow::io::plot {

/// The faces of a solid mesh on one coordinate plane through the origin (a quarter
/// model's y = 0 or z = 0 symmetry plane), as quadrilaterals (triangles, for tetrahedra)
/// of the same order.
struct PlaneSection {
  mesh::Mesh<2> mesh;                ///< coordinates (u, v) = the solid's in_plane axes
  std::vector<Index> solid_node;     ///< solid node of each section node
  std::array<int, 2> in_plane{0, 1}; ///< solid axes drawn horizontally and vertically
};

/// The Symmetry facets of `solid` on the plane {x_normal_axis = 0} (normal_axis 1
/// or 2), positively oriented in (x, other axis); each boundary edge of the section
/// carries the label of the solid facet that meets the plane there (so the die and
/// the container wall are drawn as in a plane picture). Empty mesh when no facet
/// lies on that plane.
PlaneSection symmetry_section(const mesh::Mesh<3>& solid, int normal_axis);

/// The same for the facets of `part` on the plane {x_normal_axis = plane_at} (e.g. the
/// exit: "front" on x = x_end, drawn in (y, z)); in_plane is the other two axes in order.
PlaneSection boundary_section(const mesh::Mesh<3>& solid, mesh::BoundaryLabel part, int normal_axis,
                              Real plane_at);

/// `results` with its nodal fields restricted to the section's nodes: velocity the
/// two in-plane components, cell fields dropped (they belong to solid cells).
post::Results section_results(const post::Results& results, const PlaneSection& section);

} // namespace formflow::io::plot
