// SPDX-License-Identifier: MIT
// Every cell of a mesh split into 2^dim children: the nested mesh of an error estimate.
#pragma once

#include "formflow/mesh/mesh.hpp"

#include <vector>

namespace formflow::mesh {

/// A mesh refined once and, for each of its cells, the cell it was cut from.
template <int dim> struct RefinedMesh {
  Mesh<dim> mesh;
  std::vector<Index> parent; ///< one entry per cell of `mesh`: its cell in the coarse mesh
};

/// Splits every cell of `coarse` at its reference midpoints into 2^dim children of
/// the same order. The children's nodes are the parent's isoparametric map at the
/// child lattices, so the refined mesh nests exactly in `coarse` for Q1 and Q2
/// (a Q2 map restricted to a half cell is again Q2): fields prolong without
/// interpolation error, whatever made `coarse` (the structured channel, Gmsh, a
/// file, an adapted mesh). Nodes shared by neighbours are shared again, found
/// topologically (by the coarse nodes they lie between), never by coordinates.
/// A boundary facet passes to the 2^(dim−1) children touching it, with its label.
template <int dim> RefinedMesh<dim> refine_uniformly(const Mesh<dim>& coarse);

} // namespace formflow::mesh
