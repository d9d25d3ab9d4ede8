// SPDX-License-Identifier: MIT
// The mapped values of a fixed mesh, computed once: the cell and face loops run
// every nonlinear iteration on the same geometry, so re-mapping each time (a
// Jacobian, its inverse and a face tabulation per point) is wasted work.
#pragma once

#include "formflow/fem/cell_values.hpp"

#include <cstddef>
#include <functional>

namespace formflow::fem {

/// Gradients, JxW and points of CellValues at one rule for every cell.
/// Memory: n_cells · n_points · (dim · n_nodes + 1 + dim) doubles.
template <int dim> class CellValuesCache {
public:
  /// `map(cell, values)` maps `values` to `cell` (reinit, and in axisymmetry
  /// weight_by_radius): whatever it leaves in `values` is what load() restores.
  CellValuesCache(Index n_cells, CellValues<dim> values,
                  const std::function<void(Index, CellValues<dim>&)>& map);

  /// Puts cell `cell`'s mapped values into `values` (built for the same rule and order).
  void load(Index cell, CellValues<dim>& values) const;

  std::size_t bytes() const { return data_.size() * sizeof(Real); }

private:
  int n_points_ = 0, n_nodes_ = 0;
  std::size_t per_cell_ = 0; ///< doubles per cell: gradients, then JxW, then points
  std::vector<Real> data_;
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
