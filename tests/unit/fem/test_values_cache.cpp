// SPDX-License-Identifier: MIT
// The mapped-values cache restores exactly what the mapping produced, cell by
// cell (no mix-up of cells, points or the order of the stored fields).
#include "formflow/fem/values_cache.hpp"

#include "formflow/fem/lagrange.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace formflow::testing {
namespace {

using Nodes2 = fem::CellValues<2>::Gradients;

/// Curved Q2 cells (non-affine, curved edges), different for each `cell`.
Nodes2 curved_q2(int cell) {
  Nodes2 nodes(2, 9);
  for (int a = 0; a < 9; ++a) {
    const Point<2> xi = fem::reference_node<2>(2, a);
    const double s = 0.5 * (1.0 + xi.x()), t = 0.5 * (1.0 + xi.y());
    nodes.col(a) =
        Point<2>(cell + 1.3 * s + 0.2 * t + 0.1 * t * t, 0.4 + 0.9 * t + 0.15 * s * s * (cell + 1));
  }
  return nodes;
}

/// Maps to curved_q2(cell) and, like the axisymmetric problem, weights by r.
void map_weighted(Index cell, fem::CellValues<2>& values) {
  values.reinit(curved_q2(static_cast<int>(cell)));
  values.weight_by_radius();
}

TEST(CellValuesCache, LoadRestoresTheMappedValuesOfEachCell) {
  const fem::QuadratureRule<2> rule = fem::gauss_rule<2>(3);
  const int n_cells = 4;
  const fem::CellValuesCache<2> cache(n_cells, fem::CellValues<2>(2, rule), map_weighted);
  EXPECT_EQ(cache.bytes(), sizeof(Real) * n_cells * 9 * (2 * 9 + 1 + 2));
  fem::CellValues<2> fresh(2, rule), loaded(2, rule);
  // Backwards, so that a load that ignored its cell index would fail.
  for (Index cell = n_cells - 1; cell >= 0; --cell) {
    map_weighted(cell, fresh);
    cache.load(cell, loaded);
    for (int q = 0; q < rule.size(); ++q) {
      EXPECT_EQ(loaded.JxW(q), fresh.JxW(q)) << "cell " << cell << " point " << q;
      EXPECT_EQ(loaded.point(q), fresh.point(q));
      EXPECT_EQ(loaded.gradients(q), fresh.gradients(q));
      EXPECT_EQ(loaded.shape(q), fresh.shape(q));
    }
  }
  // Different cells really are different (the comparison above can fail).
  fem::CellValues<2> other(2, rule);
  cache.load(0, loaded);
  cache.load(1, other);
  EXPECT_NE(loaded.JxW(0), other.JxW(0));
  EXPECT_NE(loaded.gradients(4), other.gradients(4));
}

TEST(CellValuesCache, AListOfCellsHoldsThoseCellsOnly) {
  // A distributed run's rank caches the cells it assembles (cells 3 and 1 of 5 here,
  // in that order): it holds them, restores each one's own values, and stores no more.
  const fem::QuadratureRule<2> rule = fem::gauss_rule<2>(3);
  const std::vector<Index> own{3, 1};
  const fem::CellValuesCache<2> cache(5, fem::CellValues<2>(2, rule), map_weighted, own);
  EXPECT_EQ(cache.bytes(), sizeof(Real) * 2 * 9 * (2 * 9 + 1 + 2) + sizeof(Index) * 5);
  for (Index cell = 0; cell < 5; ++cell)
    EXPECT_EQ(cache.holds(cell), cell == 1 || cell == 3) << cell;
  fem::CellValues<2> fresh(2, rule), loaded(2, rule);
  for (const Index cell : own) {
    map_weighted(cell, fresh);
    cache.load(cell, loaded);
    for (int q = 0; q < rule.size(); ++q) {
      EXPECT_EQ(loaded.JxW(q), fresh.JxW(q)) << "cell " << cell << " point " << q;
      EXPECT_EQ(loaded.gradients(q), fresh.gradients(q));
    }
  }
}

TEST(FacetValuesCache, LoadRestoresFacesWithReplacedNormals) {
  const fem::QuadratureRule<1> rule = fem::gauss_rule<1>(3);
  const int n_faces = 4; // face k of cell k: every local face once
  const auto map = [](Index k, fem::FacetValues<2>& values) {
    values.reinit(curved_q2(static_cast<int>(k)), static_cast<int>(k));
    values.weight_by_radius();
    // As with nodal contact normals: the stored normal is whatever was set last.
    values.set_normal(1, Point<2>(0.6, 0.8 * (k % 2 == 0 ? 1.0 : -1.0)));
  };
  const fem::FacetValuesCache<2> cache(n_faces, fem::FacetValues<2>(2, rule), map);
  fem::FacetValues<2> fresh(2, rule), loaded(2, rule);
  for (Index k = n_faces - 1; k >= 0; --k) {
    map(k, fresh);
    cache.load(k, loaded);
    for (int q = 0; q < rule.size(); ++q) {
      EXPECT_EQ(loaded.JxW(q), fresh.JxW(q)) << "face " << k << " point " << q;
      EXPECT_EQ(loaded.normal(q), fresh.normal(q));
      EXPECT_EQ(loaded.point(q), fresh.point(q));
      EXPECT_EQ(loaded.shape(q), fresh.shape(q));
    }
  }
  cache.load(0, loaded);
  cache.load(1, fresh);
  EXPECT_NE(loaded.shape(0), fresh.shape(0)); // faces 0 and 1 are opposite sides
}

} // namespace
} // namespace formflow::testing
