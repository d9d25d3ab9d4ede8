// SPDX-License-Identifier: MIT
// Extrusion of a quadrilateral mesh into hexahedra.
#include "formflow/mesh/extruded_mesh.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::mesh {

int extrusion_layers(Real thickness, Real size) {
  FF_ASSERT(thickness > 0 && size > 0, "thickness and size are positive (key ranges)");
  // Both within 1e-6…1e6 (key ranges): the ratio is at most 1e12, the cap keeps
  // the int conversion defined; the memory check refuses such a mesh long before.
  return static_cast<int>(std::clamp<Real>(std::round(thickness / size), 1.0, 1e9));
}

Mesh<3> extrude_mesh(const Mesh<2>& plane, Real thickness, int layers, BoundaryLabel z_faces) {
  FF_ASSERT(layers >= 1 && thickness > 0, "at least one layer of positive thickness");
  const int order = plane.order;
  const int n_side = order + 1;
  const Index n_plane_nodes = plane.n_nodes(), n_plane_cells = plane.n_cells();
  const int levels = order * layers + 1;

  Mesh<3> mesh;
  mesh.order = order;
  mesh.nodes.resize(3, n_plane_nodes * levels);
  for (int k = 0; k < levels; ++k) {
    // The last level sits exactly on z = thickness, whatever the rounding of k/(levels − 1).
    const Real z = k + 1 == levels ? thickness : thickness * k / (levels - 1);
    for (Index n = 0; n < n_plane_nodes; ++n)
      mesh.nodes.col(k * n_plane_nodes + n) << plane.nodes(0, n), plane.nodes(1, n), z;
  }

  // Lexicographic local node (a, b, c) of a hexahedron is plane local node
  // b·n_side + a at lattice level layer·order + c.
  mesh.cells.resize(n_side * n_side * n_side, n_plane_cells * layers);
  for (int layer = 0; layer < layers; ++layer)
    for (Index c = 0; c < n_plane_cells; ++c) {
      const Index cell = layer * n_plane_cells + c;
      for (int level = 0; level < n_side; ++level)
        for (int in_plane = 0; in_plane < n_side * n_side; ++in_plane)
          mesh.cells(level * n_side * n_side + in_plane, cell) =
              (layer * order + level) * n_plane_nodes + plane.cells(in_plane, c);
    }

  for (int layer = 0; layer < layers; ++layer)
    for (const BoundaryFacet& facet : plane.facets)
      mesh.facets.push_back({layer * n_plane_cells + facet.cell, facet.local_face, facet.label});
  for (Index c = 0; c < n_plane_cells; ++c) {
    mesh.facets.push_back({c, 4, z_faces});
    mesh.facets.push_back({(layers - 1) * n_plane_cells + c, 5, z_faces});
  }
  return mesh;
}

} // namespace formflow::mesh
