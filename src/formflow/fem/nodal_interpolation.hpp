// SPDX-License-Identifier: MIT
// A nodal vector field of one mesh evaluated at the nodes of another (mesh sequencing).
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/mesh/mesh.hpp"

namespace formflow::fem {

/// The isoparametric field `source_values` (node-major, `components` per node) of
/// `source` evaluated at every node of `target`: each target node is located in a
/// source cell (bounding-box buckets, then Newton on the cell's geometry map) and
/// the source shape functions are evaluated there. When the meshes nest (a
/// structured mesh and its refinement by 2) this is exact prolongation of the
/// source field. A target node outside every source cell (a curved boundary
/// approximated differently) takes the value at the nearest reference point of
/// the cell it misses by least, i.e. the field is extended continuously.
template <int dim>
VectorX interpolate_nodal_field(const mesh::Mesh<dim>& source, const VectorX& source_values,
                                int components, const mesh::Mesh<dim>& target);

} // namespace formflow::fem
