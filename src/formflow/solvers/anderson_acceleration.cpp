// SPDX-License-Identifier: MIT
// Anderson mixing (Walker–Ni type II) with its restarts.
#include "formflow/solvers/anderson_acceleration.hpp"

#include "formflow/core/error.hpp"

#include <Eigen/QR>

#include <cmath>

namespace formflow::solvers {

AndersonAcceleration::AndersonAcceleration(int depth, const NonlinearProblem* ghosted)
    : depth_(depth), ghosted_(ghosted) {
  FF_ASSERT(depth >= 1, "Anderson acceleration needs at least one difference column");
}

void AndersonAcceleration::forget() {
  residual_differences_.clear();
  image_differences_.clear();
  last_residual_.resize(0);
  last_image_.resize(0);
  last_mixed_ = false;
}

void AndersonAcceleration::restart() {
  residual_differences_.clear();
  image_differences_.clear();
  ++restarts_;
}

VectorX AndersonAcceleration::next(const VectorX& iterate, const VectorX& image, bool may_mix) {
  FF_ASSERT(iterate.size() == image.size(), "an iterate and its image have one size");
  VectorX residual = image - iterate;
  const bool after_mix = last_mixed_;
  last_mixed_ = false;
  last_columns_ = 0;
  if (last_residual_.size() == residual.size()) {
    // A mix that left a larger residual than its start had is worse than the plain step,
    // which shrinks it (by the contraction ρ < 1): the history misleads, drop it.
    if (after_mix && norm(residual) > norm(last_residual_)) {
      restart();
    } else {
      residual_differences_.push_back(residual - last_residual_);
      image_differences_.push_back(image - last_image_);
      if (static_cast<int>(residual_differences_.size()) > depth_) {
        residual_differences_.pop_front();
        image_differences_.pop_front();
      }
    }
  }
  last_image_ = image;
  last_residual_ = std::move(residual);
  const auto columns = static_cast<Index>(residual_differences_.size());
  if (!may_mix || columns == 0) return image;

  if (ghosted_) {
    const std::optional<VectorX> weights = ghosted_weights(columns);
    if (!weights) return image;
    VectorX mixed = image;
    for (Index j = 0; j < columns; ++j) mixed -= (*weights)[j] * image_differences_[j];
    last_mixed_ = true;
    last_columns_ = static_cast<int>(columns);
    return mixed;
  }
  MatrixX differences(last_residual_.size(), columns);
  for (Index j = 0; j < columns; ++j) differences.col(j) = residual_differences_[j];
  const Eigen::ColPivHouseholderQR<MatrixX> qr(differences);
  // Column pivoting orders R's diagonal by decreasing magnitude: its ends bound the
  // condition from below, the estimate the restart needs.
  const Real largest = std::abs(qr.matrixQR()(0, 0));
  const Real smallest = std::abs(qr.matrixQR()(columns - 1, columns - 1));
  if (!(smallest * anderson_max_condition > largest)) {
    restart();
    return image;
  }
  const VectorX weights = qr.solve(last_residual_);
  if (!weights.allFinite()) {
    restart();
    return image;
  }
  VectorX mixed = image;
  for (Index j = 0; j < columns; ++j) mixed -= weights[j] * image_differences_[j];
  last_mixed_ = true;
  last_columns_ = static_cast<int>(columns);
  return mixed;
}

std::optional<VectorX> AndersonAcceleration::ghosted_weights(Index columns) {
  // [ΔF f] = Q R over the ranks' rows (TSQR): min ‖ΔF γ − f‖ = min ‖R₁ γ − r‖ with R₁
  // R's first c columns and r its last, a (c + 1) × c problem every rank solves alike.
  MatrixX augmented(last_residual_.size(), columns + 1);
  for (Index j = 0; j < columns; ++j) augmented.col(j) = residual_differences_[j];
  augmented.col(columns) = last_residual_;
  const MatrixX r = ghosted_->r_factor(augmented);
  const Eigen::ColPivHouseholderQR<MatrixX> qr(r.leftCols(columns));
  const Real largest = std::abs(qr.matrixQR()(0, 0));
  const Real smallest = std::abs(qr.matrixQR()(columns - 1, columns - 1));
  if (!(smallest * anderson_max_condition > largest)) {
    restart();
    return std::nullopt;
  }
  VectorX weights = qr.solve(VectorX(r.col(columns)));
  if (!weights.allFinite()) {
    restart();
    return std::nullopt;
  }
  return weights;
}

} // namespace formflow::solvers
