// SPDX-License-Identifier: MIT
// The adaptive cycles' marking and the next mesh's target sizes (post/adaptivity.hpp).
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/post/adaptivity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace formflow::post {
namespace {

TEST(Adaptivity, CoarseningTakesTheSmallestIndicatorsUpToItsShare) {
  // |η| = 1, 2, 3, 4, 10 (Σ = 20): a share of 0.15 (3) takes 1 and 2, not 3 (6 > 3).
  const VectorX indicators = (VectorX(5) << 4.0, -1.0, 10.0, 2.0, -3.0).finished();
  EXPECT_EQ(coarsening_marking(indicators, 0.15),
            (std::vector<bool>{false, true, false, true, false}));
  EXPECT_EQ(coarsening_marking(indicators, 0.0), std::vector<bool>(5, false)) << "0: never";
  // Dörfler's θ = ½ (10) marks 10 alone; what it marks and what coarsening takes are
  // disjoint for any share below 1 − θ.
  const std::vector<bool> marked = dorfler_marking(indicators, 0.5);
  const std::vector<bool> coarsened = coarsening_marking(indicators, 0.45);
  for (std::size_t k = 0; k < marked.size(); ++k) EXPECT_FALSE(marked[k] && coarsened[k]) << k;
}

TEST(Adaptivity, SizesHalveDoubleUpToTheCaseSizeAndGradeByTwo) {
  // The paper's channel at h = 0.5: every cell side 0.5. A side is √(t/2), t twice the
  // area from the shoelace sum of four products of coordinates up to L = 10: its eight
  // roundings put t within 8 eps L², so a side of 0.5 is within that over 4 · 0.5, and
  // a doubled one (the largest checked) within 8 eps L² itself.
  const mesh::Mesh<2> mesh = mesh::make_channel_mesh(mesh::ChannelGeometry{}, 0.5, 2);
  const double tolerance = 8 * std::numeric_limits<double>::epsilon() * 10 * 10;
  const auto n = static_cast<std::size_t>(mesh.n_cells());
  std::vector<bool> marked(n, false), coarsened(n, false);
  const VectorX unchanged = target_node_sizes(mesh, marked, coarsened, 2.0);
  EXPECT_NEAR(unchanged.minCoeff(), 0.5, tolerance);
  EXPECT_NEAR(unchanged.maxCoeff(), 0.5, tolerance);
  // Every cell coarsened: sides double, but not beyond the case's size.
  std::fill(coarsened.begin(), coarsened.end(), true);
  EXPECT_NEAR(target_node_sizes(mesh, marked, coarsened, 2.0).maxCoeff(), 1.0, tolerance);
  EXPECT_NEAR(target_node_sizes(mesh, marked, coarsened, 0.75).maxCoeff(), 0.75, tolerance);
  EXPECT_NEAR(target_node_sizes(mesh, marked, coarsened, 0.25).minCoeff(), 0.5, tolerance)
      << "a cell already larger than the case's size keeps its side";
  // One cell marked, all others coarsened: its nodes take 0.25; within any cell no
  // node exceeds twice the cell's smallest (the grading Gmsh needs to recombine; the
  // sweep sets an offending size to exactly 2 · smallest, so no tolerance).
  marked[0] = true;
  coarsened[0] = false;
  const VectorX sizes = target_node_sizes(mesh, marked, coarsened, 2.0);
  for (int a = 0; a < mesh.nodes_per_cell(); ++a)
    EXPECT_NEAR(sizes[mesh.cells(a, 0)], 0.25, tolerance);
  for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
    Real smallest = sizes[mesh.cells(0, cell)], largest = smallest;
    for (int a = 0; a < mesh.nodes_per_cell(); ++a) {
      smallest = std::min(smallest, sizes[mesh.cells(a, cell)]);
      largest = std::max(largest, sizes[mesh.cells(a, cell)]);
    }
    EXPECT_LE(largest, 2 * smallest) << "cell " << cell;
  }
  EXPECT_NEAR(sizes.maxCoeff(), 1.0, tolerance) << "far from the marked cell, coarsened";
}

} // namespace
} // namespace formflow::post
