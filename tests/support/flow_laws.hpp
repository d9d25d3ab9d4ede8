// SPDX-License-Identifier: MIT
// The flow laws the tests exercise besides the paper's (5.4), with their test parameters.
#pragma once

#include "formflow/physics/flow_law.hpp"

namespace formflow::testing {

/// σ_p = √3 K (√3 ε̄̇)^m.
inline physics::FlowLaw norton_hoff(double k, double m) {
  physics::FlowLaw law;
  law.kind = physics::FlowLawKind::NortonHoff;
  law.K = k;
  law.m = m;
  return law;
}

/// A Hensel–Spittel law with every term active (aluminium-like coefficients,
/// 700 °C, strain 0.5).
inline physics::FlowLaw hensel_spittel() {
  physics::FlowLaw law;
  law.kind = physics::FlowLawKind::HenselSpittel;
  law.hs_A = 300.0;
  law.hs_m1 = -0.002;
  law.hs_m2 = 0.1;
  law.hs_m3 = 0.05;
  law.hs_m4 = -0.01;
  law.hs_m8 = 1e-4;
  law.temperature = 700.0;
  law.strain = 0.5;
  return law;
}

/// σ_p = σ₀ at every rate.
inline physics::FlowLaw perfectly_plastic(double sigma0) {
  physics::FlowLaw law;
  law.kind = physics::FlowLawKind::PerfectlyPlastic;
  law.sigma0 = sigma0;
  return law;
}

} // namespace formflow::testing
