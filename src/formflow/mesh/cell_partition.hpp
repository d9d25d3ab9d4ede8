// SPDX-License-Identifier: MIT
// Which MPI rank assembles which cell (issue 20): a geometric split into slabs
// along x, the extrusion axis of every channel mesh, with equal cell counts.
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <vector>

namespace formflow::mesh {

/// The part (0 .. parts−1) of every cell: cells ordered by the x of their centroid
/// (ties by index, so every rank computes the same split), then cut into `parts`
/// runs whose sizes differ by at most one. A slab along the flow keeps the
/// interface between parts small (one cross-section per cut) for the channel meshes;
/// meshes from files would want a graph partitioner (PT-Scotch) instead.
template <int dim> std::vector<int> slab_partition(const Mesh<dim>& mesh, int parts);

} // namespace formflow::mesh
