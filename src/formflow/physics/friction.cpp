// SPDX-License-Identifier: MIT
// The mollifier of the contact pressure.
#include "formflow/physics/friction.hpp"

#include "formflow/core/error.hpp"

#include <cmath>

namespace formflow::physics {

NonlocalAverage::NonlocalAverage(const MatrixX& points, const std::vector<Real>& weights,
                                 Real radius) {
  const int n = static_cast<int>(points.cols());
  FF_ASSERT(static_cast<int>(weights.size()) == n, "one weight per point");
  offsets_.reserve(n + 1);
  offsets_.push_back(0);
  // Γ3 has O(√dofs) points, so the all-pairs search costs less than one assembly.
  for (int i = 0; i < n; ++i) {
    Real total = 0.0;
    const std::size_t first = neighbours_.size();
    for (int j = 0; j < n; ++j) {
      const bool near = (i == j) || (radius > 0 && (points.col(i) - points.col(j)).norm() < radius);
      if (!near) continue;
      neighbours_.push_back(j);
      coefficients_.push_back(weights[j]);
      total += weights[j];
    }
    for (std::size_t k = first; k < coefficients_.size(); ++k) coefficients_[k] /= total;
    offsets_.push_back(static_cast<int>(neighbours_.size()));
  }
}

void NonlocalAverage::apply(const std::vector<Real>& pressure, std::vector<Real>& averaged) const {
  averaged.assign(pressure.size(), 0.0);
  for (int i = 0; i < size(); ++i)
    for (int k = offsets_[i]; k < offsets_[i + 1]; ++k)
      averaged[i] += coefficients_[k] * pressure[neighbours_[k]];
}

void NonlocalAverage::apply_transpose(const std::vector<Real>& values,
                                      std::vector<Real>& spread) const {
  spread.assign(values.size(), 0.0);
  for (int i = 0; i < size(); ++i)
    for (int k = offsets_[i]; k < offsets_[i + 1]; ++k)
      spread[neighbours_[k]] += coefficients_[k] * values[i];
}

} // namespace formflow::physics
