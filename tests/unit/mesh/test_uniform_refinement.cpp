// SPDX-License-Identifier: MIT
// Every cell split in four: topology, nesting and boundary labels of the refined mesh.
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/mesh/die_channel_mesh.hpp"
#include "formflow/mesh/uniform_refinement.hpp"
#include "formflow/post/load_error_estimate.hpp"

#include <gtest/gtest.h>

#include <array>
#include <map>

namespace formflow::mesh {
namespace {

ChannelGeometry wedge() {
  ChannelGeometry geometry;
  geometry.die = DieShape::Wedge;
  geometry.die_angle = 30.0;
  return geometry;
}

/// Facets per label.
std::map<BoundaryLabel, int> facet_counts(const Mesh<2>& mesh) {
  std::map<BoundaryLabel, int> counts;
  for (const BoundaryFacet& facet : mesh.facets) ++counts[facet.label];
  return counts;
}

class UniformRefinement : public ::testing::TestWithParam<int> {};

TEST_P(UniformRefinement, MatchesTheStructuredChannelAtHalfTheSize) {
  // The mapped wedge channel: the structured generator at size/2 makes the same
  // topology (counts of cells, nodes and labelled facets), whatever the node positions.
  const int order = GetParam();
  const Mesh<2> coarse = make_die_channel_mesh(wedge(), 1.0, order);
  const Mesh<2> half = make_die_channel_mesh(wedge(), 0.5, order);
  const RefinedMesh<2> refined = refine_uniformly(coarse);
  EXPECT_EQ(refined.mesh.n_cells(), 4 * coarse.n_cells());
  EXPECT_EQ(refined.mesh.n_cells(), half.n_cells());
  // Shared nodes shared once: any duplicate would raise the count.
  EXPECT_EQ(refined.mesh.n_nodes(), half.n_nodes());
  EXPECT_EQ(facet_counts(refined.mesh), facet_counts(half));
}

TEST_P(UniformRefinement, NestsExactlyAndKnowsEachParent) {
  // The children's nodes are the parent's geometry map at the half-cell lattices:
  // the coarse mesh's coordinate field, interpolated at the fine nodes, gives them
  // back (the inverse map's Newton stops at 1e-13 in reference coordinates, cells
  // are of size ≈ 1, so 1e-11 is round-off with margin).
  const int order = GetParam();
  const Mesh<2> coarse = make_die_channel_mesh(wedge(), 1.0, order);
  const RefinedMesh<2> refined = refine_uniformly(coarse);
  VectorX coordinates(2 * coarse.n_nodes());
  for (Index node = 0; node < coarse.n_nodes(); ++node)
    coordinates.segment<2>(2 * node) = coarse.nodes.col(node);
  const VectorX at_fine = fem::interpolate_nodal_field(coarse, coordinates, 2, refined.mesh);
  for (Index node = 0; node < refined.mesh.n_nodes(); ++node)
    EXPECT_LT((at_fine.segment<2>(2 * node) - refined.mesh.nodes.col(node)).norm(), 1e-11)
        << "node " << node;
  // The parent found geometrically (post/load_error_estimate.hpp) is the one recorded.
  EXPECT_EQ(post::parent_cells(coarse, refined.mesh), refined.parent);
}

TEST_P(UniformRefinement, FacetsLieOnTheirParentsFaces) {
  // Every node of a fine facet lies on the line through its parent facet's end
  // nodes (the wedge channel's faces are straight): a facet handed to the wrong
  // child, or with the wrong local face, would leave it. Distances of order 1
  // (cells of size 1), so 1e-12 is round-off.
  const int order = GetParam();
  const Mesh<2> coarse = make_die_channel_mesh(wedge(), 1.0, order);
  const RefinedMesh<2> refined = refine_uniformly(coarse);
  const int n = coarse.nodes_per_side();
  for (const BoundaryFacet& facet : refined.mesh.facets) {
    const Index parent = refined.parent[static_cast<std::size_t>(facet.cell)];
    const std::vector<int> parent_face = face_local_nodes<2>(n, facet.local_face);
    const Point<2> a = coarse.nodes.col(coarse.cells(parent_face.front(), parent));
    const Point<2> b = coarse.nodes.col(coarse.cells(parent_face.back(), parent));
    const Point<2> direction = (b - a).normalized();
    for (int local : face_local_nodes<2>(n, facet.local_face)) {
      const Point<2> x = refined.mesh.nodes.col(refined.mesh.cells(local, facet.cell));
      const Point<2> offset = x - a;
      EXPECT_LT(std::abs(offset.x() * direction.y() - offset.y() * direction.x()), 1e-12);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Q1AndQ2, UniformRefinement, ::testing::Values(1, 2));

} // namespace
} // namespace formflow::mesh
