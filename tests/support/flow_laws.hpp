// SPDX-License-Identifier: MIT
// The flow laws the tests exercise besides the paper's (5.4), with their test parameters.
#pragma once

#include "formflow/physics/flow_law.hpp"

namespace formflow::testing {

/// σ_p = √3 K (√3 ε̄̇)^m.
inline physics::FlowLaw norton_hoff(double k, double m) {
  physics::FlowLaw law;
  law.model = physics::NortonHoff{};
  law.as<physics::NortonHoff>().K = k;
  law.as<physics::NortonHoff>().m = m;
  return law;
}

/// A Hensel–Spittel law with every term active (aluminium-like coefficients,
/// 700 °C, strain 0.5).
inline physics::FlowLaw hensel_spittel() {
  physics::FlowLaw law;
  law.model = physics::HenselSpittel{};
  law.as<physics::HenselSpittel>().A = 300.0;
  law.as<physics::HenselSpittel>().m1 = -0.002;
  law.as<physics::HenselSpittel>().m2 = 0.1;
  law.as<physics::HenselSpittel>().m3 = 0.05;
  law.as<physics::HenselSpittel>().m4 = -0.01;
  law.as<physics::HenselSpittel>().m8 = 1e-4;
  law.as<physics::HenselSpittel>().temperature = 700.0;
  law.as<physics::HenselSpittel>().strain = 0.5;
  return law;
}

/// σ_p = σ₀ at every rate.
inline physics::FlowLaw perfectly_plastic(double sigma0) {
  physics::FlowLaw law;
  law.model = physics::PerfectlyPlastic{};
  law.as<physics::PerfectlyPlastic>().sigma0 = sigma0;
  return law;
}

} // namespace formflow::testing
