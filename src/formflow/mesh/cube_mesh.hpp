// SPDX-License-Identifier: MIT
// The unit cube in hexahedra with smooth or random interior-vertex perturbation (3D
// manufactured solutions).
#pragma once

#include "formflow/mesh/box_mesh.hpp"

namespace formflow::mesh {

/// `cells`³ hexahedra of polynomial `order` (1 or 2) on [0, 1]³, the interior
/// vertices moved by `distortion` as make_box_mesh moves them in 2D (smooth: one
/// fixed map, vanishing on the boundary, with different components so that the
/// cells are not parallelepipeds; random: up to amplitude × the cell side in
/// each direction). The higher-order nodes of a Q2 cell sit where the trilinear
/// map of its eight vertices puts them (straight edges), so every cell is a
/// trilinear image of the reference cube. Labels as make_box_mesh, z like y:
/// rear x = 0, front x = 1, symmetry y = 0 and z = 0, free_exit y = 1 and z = 1.
Mesh<3> make_unit_cube_mesh(int cells, int order, const BoxDistortion& distortion = {});

} // namespace formflow::mesh
