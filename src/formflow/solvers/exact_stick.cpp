// SPDX-License-Identifier: MIT
// The Newton step condensed onto exact constraints (see exact_stick.hpp for why).
#include "formflow/solvers/exact_stick.hpp"

#include "formflow/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::solvers {

StepCondensation::StepCondensation(std::vector<StepConstraint> constraints, Index n_free)
    : constraints_(std::move(constraints)), n_free_(n_free) {
  for ([[maybe_unused]] const StepConstraint& c : constraints_)
    FF_ASSERT(c.rows.size() == c.coefficients.size(), "one coefficient per row");
}

VectorX StepCondensation::project(const VectorX& x) const {
  VectorX y = x;
  for (const StepConstraint& c : constraints_) {
    Real along = 0.0;
    for (std::size_t i = 0; i < c.rows.size(); ++i) along += c.coefficients[i] * x[c.rows[i]];
    for (std::size_t i = 0; i < c.rows.size(); ++i) y[c.rows[i]] -= along * c.coefficients[i];
  }
  return y;
}

VectorX StepCondensation::particular() const {
  VectorX g = VectorX::Zero(n_free_);
  for (const StepConstraint& c : constraints_)
    for (std::size_t i = 0; i < c.rows.size(); ++i) g[c.rows[i]] += c.target * c.coefficients[i];
  return g;
}

std::vector<Real> StepCondensation::components(const VectorX& x) const {
  std::vector<Real> values;
  values.reserve(constraints_.size());
  for (const StepConstraint& c : constraints_) {
    Real along = 0.0;
    for (std::size_t i = 0; i < c.rows.size(); ++i) along += c.coefficients[i] * x[c.rows[i]];
    values.push_back(along);
  }
  return values;
}

void StepCondensation::condense(const assembly::SparseMatrix& lower,
                                assembly::SparseMatrix& condensed) const {
  using Triplet = Eigen::Triplet<Real, Index>;
  // P and E = Σ α_k c_k c_kᵀ as sparse matrices; the full symmetric T.
  const assembly::SparseMatrix full = lower.selfadjointView<Eigen::Lower>();
  std::vector<Triplet> projector, added;
  for (const StepConstraint& c : constraints_) {
    Real stiffness = 0.0; // α = cᵀ T c
    for (std::size_t i = 0; i < c.rows.size(); ++i)
      for (std::size_t j = 0; j < c.rows.size(); ++j)
        stiffness += c.coefficients[i] * full.coeff(c.rows[i], c.rows[j]) * c.coefficients[j];
    FF_ASSERT(stiffness > 0, "a constrained direction with stiffness");
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
      for (std::size_t j = 0; j < c.rows.size(); ++j) {
        projector.emplace_back(c.rows[i], c.rows[j], -c.coefficients[i] * c.coefficients[j]);
        added.emplace_back(c.rows[i], c.rows[j], stiffness * c.coefficients[i] * c.coefficients[j]);
      }
    }
  }
  for (Index i = 0; i < n_free_; ++i) projector.emplace_back(i, i, 1.0);
  assembly::SparseMatrix p(n_free_, n_free_), e(n_free_, n_free_);
  p.setFromTriplets(projector.begin(), projector.end());
  e.setFromTriplets(added.begin(), added.end());
  const assembly::SparseMatrix result = assembly::SparseMatrix(p * full * p) + e;

  // Into the given pattern: entries outside it are zero (P mixes one node's dofs only).
  condensed = lower;
  std::fill(condensed.valuePtr(), condensed.valuePtr() + condensed.nonZeros(), 0.0);
  for (Index column = 0; column < condensed.outerSize(); ++column) {
    const Index begin = condensed.outerIndexPtr()[column];
    const Index end = condensed.outerIndexPtr()[column + 1];
    const Index* rows = condensed.innerIndexPtr();
    for (assembly::SparseMatrix::InnerIterator it(result, column); it; ++it) {
      if (it.row() < column) continue;
      const Index* found = std::lower_bound(rows + begin, rows + end, it.row());
      if (found == rows + end || *found != it.row()) {
        FF_ASSERT(it.value() == 0.0, "the condensed step stays in the tangent's pattern");
        continue;
      }
      condensed.valuePtr()[found - rows] = it.value();
    }
  }
}

} // namespace formflow::solvers
