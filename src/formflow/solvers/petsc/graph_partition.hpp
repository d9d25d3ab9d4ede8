// SPDX-License-Identifier: MIT
// The cells of a distributed run split by a graph partitioner (issue 20): PETSc's
// MatPartitioning with PT-Scotch (Debian's PETSc has it; no METIS there).
#pragma once

#include "formflow/mesh/cell_partition.hpp"

#include <vector>

namespace formflow::solvers::petsc {

/// The part (0 .. parts−1) of every vertex of `graph` and the partitioner's type name,
/// for mesh::GraphPartitioner:
/// rank 0 partitions the whole graph (PT-Scotch, or the -mat_partitioning_type given on
/// the command line) and broadcasts it, so every rank has the same split. Collective.
/// Throws InputError on every rank for a -mat_partitioning_type PETSc does not have;
/// empty if the partitioner failed otherwise (mesh::cell_partition then cuts slabs).
mesh::CellPartition partition_graph(const mesh::CellGraph& graph, int parts);

} // namespace formflow::solvers::petsc
