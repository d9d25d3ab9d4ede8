// SPDX-License-Identifier: MIT
// Slip-line, ideal-work and upper-bound references for wedge/conical dies (the
// same formulas as bench/forming_references.py; sources in docs/validation.md).
// Stresses in units of the shear yield stress k; angles in radians.
#pragma once

#include <cmath>

namespace formflow::testing {

/// Hill's special reduction r = 2 sin α/(1 + 2 sin α): one centred fan.
inline double hill_special_reduction(double alpha) {
  return 2 * std::sin(alpha) / (1 + 2 * std::sin(alpha));
}
/// Frictionless plane-strain drawing stress = extrusion pressure = 2k(1 + α) r there.
inline double hill_wedge_stress(double alpha) {
  return 2 * (1 + alpha) * hill_special_reduction(alpha);
}
/// Ideal (homogeneous) work, plane strain: 2k ln(1/(1 − r)).
inline double plane_ideal(double r) {
  return 2 * std::log(1 / (1 - r));
}

/// Plane-strain radial-flow upper bound, frictionless:
/// 2k [E(α | ¾)/sin α · ln(1/(1 − r)) + tan(α/2)].
inline double plane_radial_upper_bound(double alpha, double r) {
  const int n = 2000; // Simpson on a smooth integrand: exact to ~1e-13
  double e = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double weight = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    e += weight * std::sqrt(1 - 0.75 * std::pow(std::sin(i * alpha / n), 2));
  }
  e *= alpha / n / 3;
  return 2 * (e / std::sin(alpha) * std::log(1 / (1 - r)) + std::tan(alpha / 2));
}

/// Axisymmetric ideal work σ_0 ln(1/(1 − r)), σ_0 = √3 k, r the area reduction.
inline double axisymmetric_ideal(double r) {
  return std::sqrt(3.0) * std::log(1 / (1 - r));
}

/// Avitzur's conical-die upper bound, frictionless, no back tension.
inline double avitzur_upper_bound(double alpha, double r) {
  const double s2 = std::pow(std::sin(alpha), 2), c = std::sqrt(11.0 / 12.0);
  const double root = std::sqrt(1 - 11.0 / 12.0 * s2);
  const double f = (1 - std::cos(alpha) * root +
                    1 / std::sqrt(132.0) * std::log((1 + c) / (c * std::cos(alpha) + root))) /
                   s2;
  const double log_radius = 0.5 * std::log(1 / (1 - r));
  return std::sqrt(3.0) * (2 * f * log_radius) + 2 * (alpha / s2 - 1 / std::tan(alpha));
}

} // namespace formflow::testing
