// SPDX-License-Identifier: MIT
// Gmsh meshes of hexahedra (generated or read from a .msh file) as formflow solid meshes.
#pragma once

#include "formflow/mesh/gmsh_mesh.hpp"

#include <string>
#include <vector>

namespace formflow::mesh {

/// Our lexicographic local node (fem/lagrange.hpp) of node `gmsh_node` of a
/// Gmsh hexa-8 (`order` 1) or hexa-27 (`order` 2), from Gmsh's own reference
/// coordinates of the element (corners, then edge, face and centre nodes).
/// Asks Gmsh: call it while a GmshSession is open.
int lexicographic_of_gmsh_hex_node(int order, int gmsh_node);

/// Converts the current model of `session` as mesh_from_gmsh_model does in the
/// plane, one dimension up: its 3D elements become the cells (hexa-8 → Q1,
/// hexa-27 → Q2, reordered lexicographically; left-handed cells are mirrored in
/// ξ; with `shape` Simplex tetra-4 → P1, tetra-10 → P2, left-handed ones turned),
/// the cell faces used by one cell only are the boundary facets, labelled by
/// the physical *surface* groups named in `boundaries` (an empty map: surfaces
/// named like a part). A face element (quadrilateral, or triangle for tetrahedra)
/// is matched to a cell face by its corner nodes. Throws MeshFileError for: no 3D elements;
/// elements other than cells of `shape` and `order` (the other shape: Subject::Cell; prisms,
/// pyramids, 20-node serendipity hexahedra, mixed orders); a mapped name that is not a physical
/// surface; a named physical surface on the boundary that is not mapped; a mapped face element
/// inside the mesh or in two parts; boundary faces without a label. The Jacobian of the cells is
/// not checked here (io/mesh_input.cpp does).
Mesh<3> solid_mesh_from_gmsh_model(const GmshSession& session,
                                   const std::vector<PhysicalBoundary>& boundaries, int order,
                                   CellShape shape = CellShape::Cube);

/// Reads a .msh file of hexahedra through Gmsh, checked first as data exactly as
/// read_gmsh_mesh does (mesh/msh_header.hpp, mesh/msh_file.hpp), and converts it
/// with solid_mesh_from_gmsh_model.
Mesh<3> read_gmsh_solid_mesh(const std::string& path,
                             const std::vector<PhysicalBoundary>& boundaries, int order,
                             CellShape shape = CellShape::Cube);

/// Adds `mesh` to the current model of `session` as discrete entities: one
/// volume of hexa-8/hexa-27 (tetra-4/tetra-10) elements (physical volume "domain") and,
/// per boundary label in use, one surface of quad-4/quad-9 (triangle-3/6) elements (physical
/// surface named label_name). Written with write_gmsh_mesh, it reads back as
/// the same mesh (tests; a generated solid channel saved for other tools).
void add_solid_mesh_to_gmsh_model(const GmshSession& session, const Mesh<3>& mesh);

} // namespace formflow::mesh
