// SPDX-License-Identifier: MIT
// What reading a Gmsh model into a Mesh<dim> does alike in the plane and in solids:
// opening a checked .msh copy, numbering the nodes, labelling the boundary facets.
#pragma once

#include "formflow/mesh/gmsh_mesh.hpp"

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace formflow::mesh::gmsh_reading {

/// Gmsh element type numbers (gmsh.h getElementProperties, .msh format documentation).
constexpr int line2 = 1, line3 = 8, quad4 = 3, quad9 = 10, quad8 = 16, hexa8 = 5, hexa27 = 12,
              hexa20 = 17, triangle3 = 2, triangle6 = 9, tetra4 = 4, tetra10 = 11;

/// Gmsh's name of element type `type` ("Quadrilateral 9", "Hexahedron 20", ...).
/// Call it while a GmshSession is open.
std::string element_type_name(int type);

/// Opens `path` in `session`, the file checked first as data: Gmsh reads only a
/// private copy of bytes that parse as MSH (mesh/msh_file.hpp), never the user's
/// path (Gmsh would run a file that is not a mesh as a script). A file Gmsh cannot
/// read is a MeshFileError (Subject::File) naming the user's path, not the copy's.
void open_checked_msh(const GmshSession& session, const std::string& path);

/// Fills `mesh.nodes` with the nodes the cells use, numbered in ascending Gmsh tag
/// order, and `mesh.cells` (already sized, (order + 1)^dim rows) from `cell_tags`,
/// the cells' Gmsh node tags in our lexicographic order, cell after cell. Returns
/// the mesh index of each used Gmsh tag.
template <int dim>
std::unordered_map<std::size_t, Index> number_nodes(const std::vector<std::size_t>& cell_tags,
                                                    Mesh<dim>& mesh);

/// Finds the cell faces used by one cell only (the boundary facets, in cell order)
/// and labels each from the physical groups of dimension dim − 1 (curves in the
/// plane, surfaces in a solid) mapped by `boundaries` (empty: the groups named like
/// a part). A group's element is matched to a facet by its corner nodes. Throws
/// MeshFileError for a mapped name that is no such group, a group on the boundary
/// that is not mapped, a group element inside the mesh or in two parts, and facets
/// left without a label.
template <int dim>
void label_facets(const std::vector<PhysicalBoundary>& boundaries, Mesh<dim>& mesh,
                  const std::unordered_map<std::size_t, Index>& index_of);

} // namespace formflow::mesh::gmsh_reading
