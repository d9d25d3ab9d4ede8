// SPDX-License-Identifier: MIT
// Nonlocal (mollified) contact pressure and the regularised Coulomb law (SPEC §1–2).
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/physics/friction_laws/coulomb.hpp"
#include "formflow/physics/friction_laws/hybrid.hpp"
#include "formflow/physics/friction_laws/tresca.hpp"
#include "formflow/physics/process.hpp"

#include <cmath>
#include <vector>

namespace formflow::physics {

/// σ̄_N(x) = (1/|Γ_h(x)|) ∫_{Γ_h(x)} (−σ_N) dΓ with Γ_h(x) = {y ∈ Γ3 : |x − y| < h}:
/// a fixed averaging operator over the quadrature points of Γ3, built once
/// because the contact boundary does not move. Radius 0 gives the local pressure.
class NonlocalAverage {
public:
  /// `points`: coordinates of the Γ3 quadrature points (dim × n, any dim);
  /// `weights`: their surface measures JxW.
  NonlocalAverage(const MatrixX& points, const std::vector<Real>& weights, Real radius);

  /// averaged[i] = Σ_j w_j p_j / Σ_j w_j over the points j within `radius` of i.
  void apply(const std::vector<Real>& pressure, std::vector<Real>& averaged) const;
  /// The transpose: spread[j] = Σ_i A_ij values[i] (the adjoint of a goal through σ̄_N).
  void apply_transpose(const std::vector<Real>& values, std::vector<Real>& spread) const;
  int size() const { return static_cast<int>(offsets_.size()) - 1; }

private:
  // Compressed rows of neighbour indices and normalised weights.
  std::vector<int> offsets_;
  std::vector<int> neighbours_;
  std::vector<Real> coefficients_;
};

/// The registration of the friction laws: calls `visit` with the threshold object of
/// friction.law (each has at(ThresholdPoint), vanishes(), needs_shear_yield). A new
/// law is one header in physics/friction_laws/ plus one case here and a key entry.
template <class Visit> decltype(auto) visit_threshold(const Friction& friction, Visit&& visit) {
  switch (friction.law) {
  case FrictionLaw::Tresca: return visit(TrescaThreshold{friction.m});
  case FrictionLaw::Hybrid: return visit(HybridThreshold{friction.mu, friction.m});
  case FrictionLaw::Coulomb: break;
  }
  return visit(CoulombThreshold{friction.mu});
}

/// τ_f and its slopes at `point` for `friction`'s law.
inline ThresholdValue friction_threshold(const Friction& friction, const ThresholdPoint& point) {
  return visit_threshold(friction, [&](const auto& law) { return law.at(point); });
}

/// True when the law needs the shear yield stress k at the contact points.
inline bool needs_shear_yield(const Friction& friction) {
  return visit_threshold(friction, [](const auto& law) { return law.needs_shear_yield; });
}

/// True when the threshold is zero at every point (μ = 0 Coulomb, m = 0 Tresca): friction
/// is "on" where a part has a law whose threshold does not vanish.
inline bool friction_vanishes(const Friction& friction) {
  return visit_threshold(friction, [](const auto& law) { return law.vanishes(); });
}

/// Secant weight of the regularised friction term (eq. 3.15):
/// τ_f / √(|u_T|² + d_T²), so that σ_T = −weight · u_T.
inline Real friction_weight(Real threshold, Real slip_speed, Real d_t) {
  return threshold / std::sqrt(slip_speed * slip_speed + d_t * d_t);
}

/// Regularised friction has no exact stick zone; a point counts as sticking when
/// its traction stays clearly below the Coulomb limit, |σ_T| < 0.99 τ_f, which is
/// |u_T| < 7.02 d_T (0.99/√(1 − 0.99²)): a slip far below the process speed.
inline bool is_sticking_regularized(Real threshold, Real slip_speed, Real d_t) {
  return threshold > 0 &&
         friction_weight(threshold, slip_speed, d_t) * slip_speed < 0.99 * threshold;
}

/// Exact Coulomb law in Alart–Curnier form: λ_T = proj_{|λ| ≤ τ_f}(t) with the trial
/// traction t = λ_T + r u_T. Returns the factor s ∈ [0, 1] with proj(t) = s t:
/// s = 1 inside the disc (stick), τ_f/|t| outside (slip), 0 when τ_f = 0.
inline Real coulomb_projection_factor(Real threshold, Real trial_norm) {
  if (threshold <= 0) return 0.0;
  return trial_norm <= threshold ? 1.0 : threshold / trial_norm;
}

} // namespace formflow::physics
