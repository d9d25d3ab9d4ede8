// SPDX-License-Identifier: MIT
// What a flow law gives at one equivalent strain rate inside its range.
#pragma once

#include "formflow/core/types.hpp"

#include <cmath>

namespace formflow::physics {

/// The secant viscosity σ_p/ε̄̇ and the slope dσ_p/dε̄̇ at one rate on [rate1, rate2]
/// (physics/flow_law.hpp continues every law linearly through the origin outside it).
struct FlowResponse {
  Real viscosity = 0.0; ///< σ_p(ε̄̇)/ε̄̇
  Real slope = 0.0;     ///< σ_p′(ε̄̇)
};

/// σ_p = C ε̄̇^m: ν = C ε̄̇^(m−1) and σ_p′ = m ν from one power (the Newton loops need
/// both at every point).
inline FlowResponse power_law_response(Real coefficient, Real exponent, Real rate) {
  const Real viscosity = coefficient * std::pow(rate, exponent - 1.0);
  return {viscosity, exponent * viscosity};
}

} // namespace formflow::physics
