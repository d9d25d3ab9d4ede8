// SPDX-License-Identifier: MIT
// Unit cross-sections of a solid channel's quarter model, meshed in the (y, z) plane.
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <vector>

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

/// A quarter disk around a rectangular core: the cross-section of a round
/// billet through a square die (mesh/round_square_die_mesh.hpp).
struct CoreRingSection {
  /// The mesh in physical (y, z); its first `core_cells` cells are the core.
  Mesh<2> mesh;
  Index core_cells = 0;
  /// The core's outer sides y = half_y and z = half_z (interior in `mesh`, the
  /// product's surface downstream of the die), labelled FreeExit.
  std::vector<BoundaryFacet> core_sides;
};

/// The quarter disk y, z ≥ 0, y² + z² ≤ radius² as an O-grid whose core block
/// is the rectangle [0, half_y] × [0, half_z] in `cells_y` × `cells_z` uniform
/// cells, and whose two curved blocks (`ring_cells` radial cells) are the
/// transfinite blend (1 − η)·(core side) + η·(arc point): the block below the
/// corner ray blends the side y = half_y with the arc from 0 to the corner's
/// angle θ_c = atan2(half_z, half_y), the block above blends z = half_z with the
/// arc from θ_c to 90°, angles uniform in the side's parameter, so every node at
/// η = 1 (Q2 mid-edge nodes too) lies on the true circle. A blend of a segment
/// inside the circle with the arc has Jacobian determinant of one sign
/// everywhere (the segment's points are nearer the origin than the arc's), so no
/// cell degenerates while the corner is strictly inside the circle. Facets: the
/// axes Symmetry, the arc Container. Cells positively oriented in (y, z).
/// Precondition: half_y² + half_z² < radius².
CoreRingSection make_core_ring_section(Real radius, Real half_y, Real half_z, int cells_y,
                                       int cells_z, int ring_cells, int order);

} // namespace formflow::mesh
