// SPDX-License-Identifier: MIT
// The cheap cycles' calibration, predictions and endgame.
#include "formflow/app/cheap_cycles.hpp"

#include "formflow/post/load_error_estimate.hpp"

#include <cmath>

namespace formflow::app {

void CheapCycles::calibrate(const post::LoadErrorEstimate& full, Real linearised_change) {
  const Real scale = full.enriched_change / linearised_change;
  settled_per_linearised_ = std::isfinite(scale) && scale > 0.0 ? scale : 0.0;
  ratio_ = full.ratio;
  if (full.penalty_change) regularisations_ = std::abs(*full.penalty_change);
}

CheapCycles::Prediction CheapCycles::predict(Real linearised_change, Real load, Real target) const {
  const Real change = settled_per_linearised_ * linearised_change;
  Prediction prediction;
  prediction.estimate = post::discretisation_tail(change, ratio_) + regularisations_;
  const Real refined_error = post::tail_beyond_refined(change, ratio_) + regularisations_;
  prediction.may_stop = prediction.estimate <= target * std::abs(load) ||
                        refined_error <= target * std::abs(load + change);
  return prediction;
}

} // namespace formflow::app
