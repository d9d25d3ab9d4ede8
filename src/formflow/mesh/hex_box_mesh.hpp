// SPDX-License-Identifier: MIT
// Structured hexahedral mesh of a rectangular box (the first 3D mesh source).
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <array>

namespace formflow::mesh {

/// `cells[0]` × `cells[1]` × `cells[2]` congruent hexahedra of polynomial
/// `order` (1: 8 nodes, 2: 27 nodes, lexicographic, x fastest) on the box
/// [lower, upper]. Every box face is one boundary part: `face_labels[2·axis +
/// side]` (side 0 at x_axis = lower, 1 at upper), the numbering of the cells'
/// own local faces, so face k of the box is made of local faces k of its cells.
Mesh<3> make_hex_box_mesh(const Point<3>& lower, const Point<3>& upper,
                          const std::array<int, 3>& cells, int order,
                          const std::array<BoundaryLabel, 6>& face_labels);

} // namespace formflow::mesh
