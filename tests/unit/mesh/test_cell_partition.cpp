// SPDX-License-Identifier: MIT
// The cells' adjacency a graph partitioner splits (issue 20: cells sharing a node) and
// mesh::cell_partition's rule: a partitioner's split where it is one, slabs otherwise.
#include "formflow/mesh/box_mesh.hpp"
#include "formflow/mesh/cell_graph.hpp"
#include "formflow/mesh/cell_partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace formflow::mesh {
namespace {

/// A box of nx × ny cells, cell (i, j) numbered i + nx j (make_box_mesh's order).
Mesh<2> partition_box(Index nx, Index ny) {
  return make_box_mesh(Point<2>(0.0, 0.0), Point<2>(static_cast<Real>(nx), static_cast<Real>(ny)),
                       nx, ny, 2);
}

TEST(CellGraph, NeighboursAreTheCellsSharingANodeAscendingWithoutSelf) {
  constexpr Index nx = 4, ny = 3;
  const Mesh<2> mesh = partition_box(nx, ny);
  const CellGraph graph = cell_graph(mesh);
  ASSERT_EQ(graph.n_cells(), nx * ny);
  for (Index j = 0; j < ny; ++j)
    for (Index i = 0; i < nx; ++i) {
      const Index cell = i + nx * j;
      // On a structured grid, cells share a node iff their (i, j) differ by at most 1 each
      // (a face, an edge or a corner: the corner couplings a facet graph would miss).
      std::vector<Index> expected;
      for (Index jj = std::max<Index>(j - 1, 0); jj <= std::min(j + 1, ny - 1); ++jj)
        for (Index ii = std::max<Index>(i - 1, 0); ii <= std::min(i + 1, nx - 1); ++ii)
          if (ii != i || jj != j) expected.push_back(ii + nx * jj);
      const std::vector<Index> neighbours(graph.neighbours.begin() + graph.offsets[cell],
                                          graph.neighbours.begin() + graph.offsets[cell + 1]);
      EXPECT_EQ(neighbours, expected) << "cell " << cell;
    }
}

TEST(CellPartition, APartitionersSplitIsKeptWithItsName) {
  const Mesh<2> mesh = partition_box(4, 3);
  const GraphPartitioner by_row = [](const CellGraph& graph, int parts) {
    CellPartition split{std::vector<int>(static_cast<std::size_t>(graph.n_cells())), "rows"};
    for (Index cell = 0; cell < graph.n_cells(); ++cell)
      split.part[cell] = static_cast<int>((cell / 4) % parts);
    return split;
  };
  const CellPartition split = cell_partition(mesh, 3, by_row);
  EXPECT_EQ(split.method, "rows");
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) EXPECT_EQ(split.part[cell], cell / 4);
}

TEST(CellPartition, SlabsWhereThePartitionersSplitIsNoneOrNotOne) {
  const Mesh<2> mesh = partition_box(4, 3);
  const std::vector<int> slabs = slab_partition(mesh, 2);
  const auto returning = [](std::vector<int> part) -> GraphPartitioner {
    return [part](const CellGraph&, int) { return CellPartition{part, "broken"}; };
  };
  std::vector<int> all_in_part_0(12, 0), out_of_range(12, 0), short_one(11, 0);
  for (std::size_t c = 0; c < 12; ++c) out_of_range[c] = c % 2 == 0 ? 0 : 2; // 2 of 0..1
  for (std::size_t c = 0; c < 11; ++c) short_one[c] = static_cast<int>(c % 2);
  // No partitioner, a failed one (empty), one that leaves rank 1 without cells (every
  // rank must own rows), one naming a part that does not exist, one a cell short.
  for (const GraphPartitioner& partitioner :
       {GraphPartitioner{}, returning({}), returning(all_in_part_0), returning(out_of_range),
        returning(short_one)}) {
    const CellPartition split = cell_partition(mesh, 2, partitioner);
    EXPECT_EQ(split.method, "slabs");
    EXPECT_EQ(split.part, slabs);
  }
}

} // namespace
} // namespace formflow::mesh
