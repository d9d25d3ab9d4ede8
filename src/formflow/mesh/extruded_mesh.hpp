// SPDX-License-Identifier: MIT
// A plane mesh extruded in z into hexahedra (the slab section of a solid channel).
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// Layers of about `size` over `thickness`: round(thickness/size), at least one.
/// The slab needs no thickness that fits the cells exactly: the plane-strain
/// solution is independent of z, so any layering represents it.
int extrusion_layers(Real thickness, Real size);

/// `plane` (Q1 or Q2 quadrilaterals, positively oriented) extruded over
/// z ∈ [0, thickness] in `layers` uniform layers: hexahedra of the same order,
/// cell (c, layer) = cells.col(layer·n_plane_cells + c), node lattice level k
/// (k = 0 … order·layers) holding a copy of every plane node, numbered
/// k·n_plane_nodes + n. Each plane facet becomes one facet per layer with the
/// same label and local face (faces 0–3 are the x and y faces in 2D and 3D);
/// the faces z = 0 (local face 4) and z = thickness (local face 5) are
/// labelled `z_faces`. The Jacobian of every hexahedron is the plane one's
/// times thickness/(2 layers): positive where the plane mesh's is.
Mesh<3> extrude_mesh(const Mesh<2>& plane, Real thickness, int layers, BoundaryLabel z_faces);

} // namespace formflow::mesh
