// SPDX-License-Identifier: MIT
// Unit cross-sections of a solid channel's quarter model, meshed in the (y, z) plane.
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// The unit square [0, 1]² of (y, z) in `cells_y` × `cells_z` uniform cells of
/// `order`, for a rectangular section scaled by its half height and half width.
/// Facets: the edges y = 0 and z = 0 are Symmetry (they sweep into the quarter
/// model's symmetry planes), the outer edges y = 1 and z = 1 are Container (a
/// placeholder: the swept face takes its column's label, mesh/swept_mesh.hpp).
/// Cells are positively oriented in (y, z).
Mesh<2> make_unit_square_section(int cells_y, int cells_z, int order);

/// The unit quarter disk y, z ≥ 0, y² + z² ≤ 1 as an O-grid: a square core
/// [0, s]² of m × m cells and two curved blocks of m (tangential) × k (radial)
/// cells between the core's sides and the arc, m = max(1, ⌊n/2⌋),
/// k = max(1, n − m), s = m/(m + k) ≤ ½, so `radial_cells` = n = m + k cells
/// lie along each axis (as many as the plane channel's rows) and the core's
/// corner (s, s) stays well inside the circle: no cell degenerates. The curved
/// blocks are the transfinite blend (1 − η)·(core side) + η·(arc point at angle
/// ξ·45°), so every node at η = 1 — Q2 mid-edge nodes too — lies on the true
/// unit circle. Facets as make_unit_square_section (axes Symmetry, arc Container).
Mesh<2> make_quarter_disk_section(int radial_cells, int order);

} // namespace formflow::mesh
