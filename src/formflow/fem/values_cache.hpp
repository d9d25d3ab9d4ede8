// SPDX-License-Identifier: MIT
// The mapped values of a fixed mesh, computed once: the cell and face loops run
// every nonlinear iteration on the same geometry, so re-mapping each time (a
// Jacobian, its inverse and a face tabulation per point) is wasted work.
#pragma once

#include "formflow/fem/cell_values.hpp"

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

namespace formflow::fem {

/// Gradients, JxW and points of CellValues at one rule for every cell of a list.
/// Memory: cells · n_points · (dim · n_nodes + 1 + dim) doubles.
template <int dim> class CellValuesCache {
public:
  /// `map(cell, values)` maps `values` to `cell` (reinit, and in axisymmetry
  /// weight_by_radius): whatever it leaves in `values` is what load() restores. Caches
  /// `cells` of a mesh of `n_cells` (empty: all of them; a distributed run's rank keeps
  /// the cells it assembles, docs/petsc.md).
  CellValuesCache(Index n_cells, CellValues<dim> values,
                  const std::function<void(Index, CellValues<dim>&)>& map,
                  std::span<const Index> cells = {});

  /// Whether `cell`'s values are here.
  bool holds(Index cell) const { return slot_.empty() || slot_[cell] >= 0; }
  /// Puts cell `cell`'s mapped values into `values` (built for the same rule and
  /// order); `cell` must be held.
  void load(Index cell, CellValues<dim>& values) const;

  std::size_t bytes() const { return data_.size() * sizeof(Real) + slot_.size() * sizeof(Index); }

private:
  int n_points_ = 0, n_nodes_ = 0;
  std::size_t per_cell_ = 0; ///< doubles per cell: gradients, then JxW, then points
  std::vector<Real> data_;
  std::vector<Index> slot_; ///< a cell's place in data_ (−1: not held); empty: all, in order
};

/// Shape values, gradients, JxW, normals and points of FacetValues for a list of faces
/// (the contact faces Γ3, by their position in that list).
template <int dim> class FacetValuesCache {
public:
  /// `map(position, values)` maps `values` to face `position` (reinit, radius
  /// weighting, replaced normals): load() restores exactly that.
  FacetValuesCache(Index n_faces, FacetValues<dim> values,
                   const std::function<void(Index, FacetValues<dim>&)>& map);

  void load(Index position, FacetValues<dim>& values) const;

  std::size_t bytes() const { return data_.size() * sizeof(Real); }

private:
  int n_points_ = 0, n_nodes_ = 0;
  std::size_t per_face_ = 0; ///< doubles per face: shapes, gradients, then JxW, normals, points
  std::vector<Real> data_;
};

} // namespace formflow::fem
