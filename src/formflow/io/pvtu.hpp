// SPDX-License-Identifier: MIT
// fields.pvtu: the fields of a distributed run (issue 20) as VTK's parallel
// UnstructuredGrid, one piece per rank's slab of cells (mesh/cell_partition.hpp),
// which ParaView opens as one grid.
#pragma once

#include "formflow/mesh/mesh.hpp"
#include "formflow/post/results.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace formflow::io {

/// The file name of piece `part` ("fields_3.vtu").
std::string piece_name(int part);

/// fields.pvtu and its `parts` pieces, (name, text) each, the pvtu first. Piece r is a
/// fields.vtu (io/vtu.hpp) of the cells rank r assembled (`cell_ranks`, the run's
/// partition; empty: slab r of mesh::slab_partition) with the nodes they use (a node on
/// a cut is in both pieces) and their fields; its cell_id is the cell's id in the whole
/// mesh. The pvtu lists the same point and cell arrays as the pieces.
template <int dim>
std::vector<std::pair<std::string, std::string>>
fields_pvtu(const mesh::Mesh<dim>& mesh, const post::Fields& fields,
            solvers::StopReason stop_reason, int parts, std::span<const int> cell_ranks = {});

} // namespace formflow::io
