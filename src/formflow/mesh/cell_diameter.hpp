// SPDX-License-Identifier: MIT
// The size of the cells of any mesh: what "h" is when no single mesh.size made it.
#pragma once

#include "formflow/mesh/mesh.hpp"

namespace formflow::mesh {

/// Smallest and largest cell diameter of a mesh.
struct CellDiameterRange {
  Real smallest = 0.0;
  Real largest = 0.0;
};

/// The diameter of a cell is the largest distance between two of its nodes
/// (Q2 mid-side and centre nodes included, so a curved edge counts through its
/// middle node). A square of side h has diameter √2·h. {0, 0} for no cells.
template <int dim> CellDiameterRange cell_diameter_range(const Mesh<dim>& mesh);

} // namespace formflow::mesh
