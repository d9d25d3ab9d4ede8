// SPDX-License-Identifier: MIT
// Which estimate an adaptive cycle gets: the cheap (linearised) one scaled into a
// prediction, or the full (settled) one that decides every stop.
#pragma once

#include "formflow/post/results.hpp"

namespace formflow::app {

/// The cheap intermediate cycles of an adaptive run (docs/error-estimation.md,
/// "Adaptivity", step 2c). The linearised change p_{h/2} − p_h (the adjoint at the
/// prolonged solution, no settle: one factorisation on the refined mesh instead of 5–12
/// Newton steps there) misses most of the settled change for a nearly rate-insensitive
/// law, by a similar factor from mesh to mesh: cycle 0's settled/linearised ratio turns
/// it into a prediction of the full estimate. A prediction only decides *when* to pay
/// for the full estimate and which cells to mark; every stop is decided by a full one.
///
/// The endgame: once a prediction has called for the full estimate, every later cycle
/// gets the full estimate too. The run is then within a cycle or two of its target,
/// where a wrong prediction costs most: a linearised change that cancels (Hill's 30°
/// wedge, cycle 3: a ratio of 17.5 against cycle 0's 2.3) would otherwise rescale the
/// predictions that follow to 5–25× the error, and the cycles ran on past the target
/// (80 146 dofs and a bar of 0.0009 against a target of 0.0031; 53.6 s, against 11 s
/// with a full estimate on every cycle).
class CheapCycles {
public:
  struct Prediction {
    Real estimate = 0.0;   ///< the predicted full estimate of |p_h − p|
    bool may_stop = false; ///< it, or the refined mesh's predicted error, within the target
  };

  /// Calibrated on a full estimate and the linearised change of the same solution
  /// (cycle 0's). A ratio that is not positive and finite leaves it uncalibrated: every
  /// cycle then gets the full estimate.
  void calibrate(const post::LoadErrorEstimate& full, Real linearised_change);

  /// Whether the next cycle gets the cheap estimate: calibrated, and no prediction has
  /// yet called for the full one.
  bool next_cycle_cheap() const { return settled_per_linearised_ > 0.0 && !endgame_; }

  /// The full estimate predicted from a cheap cycle's linearised change at load `load`:
  /// F_s |ρ Δ_lin| / (1 − q) + |p(2ε) − p(ε)| (q and the regularisations' offset from the
  /// calibrating estimate). may_stop when it is within `target`·|load|, or the refined
  /// mesh's own predicted error (its tail beyond p_{h/2}) within `target`·|p_{h/2}|.
  Prediction predict(Real linearised_change, Real load, Real target) const;

  /// A cheap cycle got the full estimate because its prediction may stop: the cycles
  /// after it get the full estimate (the endgame).
  void prediction_called_for_full_estimate() { endgame_ = true; }

private:
  Real settled_per_linearised_ = 0.0; ///< ρ; 0: uncalibrated
  Real ratio_ = 0.5;                  ///< the tail ratio q of the calibrating estimate
  Real regularisations_ = 0.0;        ///< its |p(2ε) − p(ε)|, when it had one
  bool endgame_ = false;
};

} // namespace formflow::app
