// SPDX-License-Identifier: MIT
// Tetrahedra from a hexahedral mesh: a conforming split of every hexahedron, its Q2 lattice
// giving the P2 nodes.
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// The tetrahedra of `hexahedra` (Q1 or Q2), conforming across every face whatever the
/// cells' local orientations: each quadrilateral face is cut along the diagonal through its
/// vertex of least global node number, a rule both cells of the face apply alike. A cell
/// whose six diagonals are those of a Kuhn split (six tetrahedra around a main diagonal, no
/// new node) is cut so (a structured box always is); any other cell gets a node at its
/// centre (Q2: its centre node) and twelve tetrahedra, two per face. P2 midpoints are the
/// Q2 lattice's own nodes (hexahedron edges, face centres, the centre on a Kuhn cell's main
/// diagonal, moved onto that straight diagonal as split_into_triangles moves a square's
/// centre); the edges from an added centre get their midpoints added. Every tetrahedron is
/// positively oriented; boundary facets keep their labels, two triangles per face. With
/// `bubbles`, the P1b / P2+ nodes are appended (with_bubble_nodes). Every node a hexahedron
/// had is kept, in its place unless it is a Kuhn cell's centre.
Mesh<3> split_into_tetrahedra(const Mesh<3>& hexahedra, bool bubbles);

} // namespace formflow::mesh
