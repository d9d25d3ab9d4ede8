// SPDX-License-Identifier: MIT
// Storing and restoring mapped cell and face values.
#include "formflow/fem/values_cache.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>

namespace formflow::fem {

template <int dim>
CellValuesCache<dim>::CellValuesCache(Index n_cells, CellValues<dim> values,
                                      const std::function<void(Index, CellValues<dim>&)>& map,
                                      std::span<const Index> cells)
    : n_points_(values.n_points()), n_nodes_(values.n_nodes()) {
  per_cell_ = static_cast<std::size_t>(n_points_) * (dim * n_nodes_ + 1 + dim);
  const auto n_held = static_cast<Index>(cells.empty() ? n_cells : cells.size());
  if (!cells.empty()) {
    slot_.assign(static_cast<std::size_t>(n_cells), -1);
    for (Index k = 0; k < n_held; ++k) slot_[cells[k]] = k;
  }
  data_.resize(per_cell_ * static_cast<std::size_t>(n_held));
  for (Index k = 0; k < n_held; ++k) {
    const Index cell = cells.empty() ? k : cells[k];
    map(cell, values);
    Real* out = data_.data() + per_cell_ * static_cast<std::size_t>(k);
    for (int q = 0; q < n_points_; ++q)
      out = std::copy_n(values.gradients_[q].data(), dim * n_nodes_, out);
    out = std::copy(values.jxw_.begin(), values.jxw_.end(), out);
    for (int q = 0; q < n_points_; ++q) out = std::copy_n(values.points_[q].data(), dim, out);
  }
}

template <int dim> void CellValuesCache<dim>::load(Index cell, CellValues<dim>& values) const {
  const Index slot = slot_.empty() ? cell : slot_[cell];
  FF_ASSERT(slot >= 0, "a cell the cache holds");
  const Real* in = data_.data() + per_cell_ * static_cast<std::size_t>(slot);
  // Eigen assignments, not std::copy_n: a call to memmove per point cost more than the copy.
  using Gradients = typename CellValues<dim>::Gradients;
  for (int q = 0; q < n_points_; ++q, in += dim * n_nodes_)
    values.gradients_[q] = Eigen::Map<const Gradients>(in, dim, n_nodes_);
  for (int q = 0; q < n_points_; ++q) values.jxw_[q] = *in++;
  for (int q = 0; q < n_points_; ++q, in += dim)
    values.points_[q] = Eigen::Map<const Point<dim>>(in);
}

template <int dim>
FacetValuesCache<dim>::FacetValuesCache(Index n_faces, FacetValues<dim> values,
                                        const std::function<void(Index, FacetValues<dim>&)>& map)
    : n_points_(values.n_points()) {
  for (Index position = 0; position < n_faces; ++position) {
    map(position, values);
    if (position == 0) {
      n_nodes_ = static_cast<int>(values.shape(0).size());
      per_face_ = static_cast<std::size_t>(n_points_) * ((1 + dim) * n_nodes_ + 1 + 2 * dim);
      data_.resize(per_face_ * static_cast<std::size_t>(n_faces));
    }
    Real* out = data_.data() + per_face_ * static_cast<std::size_t>(position);
    for (int q = 0; q < n_points_; ++q) out = std::copy_n(values.shape_[q].data(), n_nodes_, out);
    for (int q = 0; q < n_points_; ++q)
      out = std::copy_n(values.gradients_[q].data(), dim * n_nodes_, out);
    out = std::copy(values.jxw_.begin(), values.jxw_.end(), out);
    for (int q = 0; q < n_points_; ++q) out = std::copy_n(values.normals_[q].data(), dim, out);
    for (int q = 0; q < n_points_; ++q) out = std::copy_n(values.points_[q].data(), dim, out);
  }
}

template <int dim>
void FacetValuesCache<dim>::load(Index position, FacetValues<dim>& values) const {
  const Real* in = data_.data() + per_face_ * static_cast<std::size_t>(position);
  for (int q = 0; q < n_points_; ++q, in += n_nodes_) {
    values.shape_[q].resize(n_nodes_);
    std::copy_n(in, n_nodes_, values.shape_[q].data());
  }
  for (int q = 0; q < n_points_; ++q, in += dim * n_nodes_) {
    values.gradients_[q].resize(dim, n_nodes_);
    std::copy_n(in, dim * n_nodes_, values.gradients_[q].data());
  }
  for (int q = 0; q < n_points_; ++q) values.jxw_[q] = *in++;
  for (int q = 0; q < n_points_; ++q, in += dim) std::copy_n(in, dim, values.normals_[q].data());
  for (int q = 0; q < n_points_; ++q, in += dim) std::copy_n(in, dim, values.points_[q].data());
}

template class CellValuesCache<2>;
template class CellValuesCache<3>;
template class FacetValuesCache<2>;
template class FacetValuesCache<3>;

} // namespace formflow::fem
