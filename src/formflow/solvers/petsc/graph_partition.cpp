// SPDX-License-Identifier: MIT
#include "formflow/solvers/petsc/graph_partition.hpp"

#include "formflow/core/error.hpp"
#include "formflow/solvers/petsc/petsc_session.hpp"

#include <petscmat.h>

#include <mpi.h>

#include <algorithm>

namespace formflow::solvers::petsc {

namespace {

/// What rank 0's partitioner did, sent to every rank so they all act alike.
enum class PartitionOutcome : int { split = 0, refused_type = 1, failed = 2 };

struct RankZeroSplit {
  PartitionOutcome outcome = PartitionOutcome::failed;
  std::vector<int> part;
  std::string method;  ///< the partitioner's type (ptscotch, average, ...)
  std::string message; ///< PETSc's words when it refused the type
};

/// Rank 0's split: MatPartitioning on the graph as a sequential MATMPIADJ. Why not the
/// distributed partitioner on every rank's rows: every rank holds the whole mesh (and so
/// the whole graph) in this slice, and one partition broadcast is the same bits on all.
RankZeroSplit partition_on_one_rank(const mesh::CellGraph& graph, int parts) {
  RankZeroSplit split;
  const auto n = static_cast<PetscInt>(graph.n_cells());
  // MatCreateMPIAdj takes the arrays over (PetscFree at MatDestroy): PETSc's own copies.
  PetscInt *offsets = nullptr, *neighbours = nullptr;
  if (PetscMalloc1(graph.offsets.size(), &offsets) != 0) return split;
  if (PetscMalloc1(std::max<std::size_t>(graph.neighbours.size(), 1), &neighbours) != 0) {
    PetscFree(offsets);
    return split;
  }
  std::copy(graph.offsets.begin(), graph.offsets.end(), offsets);
  std::copy(graph.neighbours.begin(), graph.neighbours.end(), neighbours);
  Mat adjacency = nullptr;
  if (MatCreateMPIAdj(PETSC_COMM_SELF, n, n, offsets, neighbours, nullptr, &adjacency) != 0) {
    PetscFree(offsets);
    PetscFree(neighbours);
    return split;
  }
  ErrorCapture capture;
  MatPartitioning partitioning = nullptr;
  IS owner = nullptr;
  PetscErrorCode code = MatPartitioningCreate(PETSC_COMM_SELF, &partitioning);
  if (code == 0) code = MatPartitioningSetAdjacency(partitioning, adjacency);
  if (code == 0) code = MatPartitioningSetNParts(partitioning, parts);
  if (code == 0) code = MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH);
  if (code == 0) {
    code = MatPartitioningSetFromOptions(partitioning);
    if (code == PETSC_ERR_ARG_UNKNOWN_TYPE || code == PETSC_ERR_ARG_WRONG) {
      split.outcome = PartitionOutcome::refused_type;
      split.message = capture.message();
    }
  }
  if (code == 0) code = MatPartitioningApply(partitioning, &owner);
  if (code == 0) {
    const PetscInt* entries = nullptr;
    ISGetIndices(owner, &entries);
    split.part.assign(entries, entries + n);
    ISRestoreIndices(owner, &entries);
    MatPartitioningType type = nullptr;
    MatPartitioningGetType(partitioning, &type);
    split.method = type ? type : "";
    split.outcome = PartitionOutcome::split;
  }
  if (owner) ISDestroy(&owner);
  if (partitioning) MatPartitioningDestroy(&partitioning);
  MatDestroy(&adjacency);
  return split;
}

/// `text` on rank 0 sent to every rank (collective).
void broadcast(std::string& text) {
  auto size = static_cast<long long>(text.size());
  MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, PETSC_COMM_WORLD);
  text.resize(static_cast<std::size_t>(size));
  if (size > 0) MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, PETSC_COMM_WORLD);
}

} // namespace

mesh::CellPartition partition_graph(const mesh::CellGraph& graph, int parts) {
  RankZeroSplit split;
  if (rank() == 0) split = partition_on_one_rank(graph, parts);
  // Rank 0's outcome, split and message on every rank: they decide alike.
  auto outcome = static_cast<int>(split.outcome);
  MPI_Bcast(&outcome, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  broadcast(split.message);
  broadcast(split.method);
  if (static_cast<PartitionOutcome>(outcome) == PartitionOutcome::refused_type)
    throw InputError("command line", 0, "-mat_partitioning_type", split.message,
                     "give a partitioner PETSc 3.18 has: ptscotch (the default), average, "
                     "square, hierarch, or leave it unset");
  if (static_cast<PartitionOutcome>(outcome) != PartitionOutcome::split) return {};
  auto size = static_cast<long long>(split.part.size());
  MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, PETSC_COMM_WORLD);
  split.part.resize(static_cast<std::size_t>(size));
  if (size > 0) MPI_Bcast(split.part.data(), static_cast<int>(size), MPI_INT, 0, PETSC_COMM_WORLD);
  return {std::move(split.part), std::move(split.method)};
}

} // namespace formflow::solvers::petsc
