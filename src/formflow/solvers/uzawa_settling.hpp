// SPDX-License-Identifier: MIT
// When the Uzawa steps inside one secant step may end.
#pragma once

#include "formflow/core/types.hpp"

#include <cmath>
#include <limits>

namespace formflow::solvers {

/// Uzawa steps end when the relative multiplier change falls below the
/// tolerance, or when it has stopped falling at a round-off floor: the update
/// λ ← λ + r M⁻¹B u multiplies the velocity's round-off by r (up to ρ × the
/// rigid zones' secant viscosity, ~1e6), so on some meshes the change
/// settles between 1e-8 and 1e-7 and further steps only repeat the same
/// factorised solve (seen: cases/wedge-die-drawing.toml, Q2–P1disc, d = 0,
/// every secant step spent all its Uzawa steps). A floor below √tolerance
/// counts as settled; a stall above it does not.
class UzawaSettling {
public:
  explicit UzawaSettling(Real tolerance) : tolerance_(tolerance) {}

  /// After a step with relative multiplier change `change`: true to stop stepping.
  bool settled(Real change) {
    const bool stalled = change >= previous_;
    previous_ = change;
    converged_ = change < tolerance_ || (stalled && change < std::sqrt(tolerance_));
    return converged_;
  }

  /// Whether the last step ended settled (converged to the tolerance or to the floor).
  bool converged() const { return converged_; }

private:
  Real tolerance_;
  Real previous_ = std::numeric_limits<Real>::infinity();
  bool converged_ = false;
};

} // namespace formflow::solvers
