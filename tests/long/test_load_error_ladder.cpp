// SPDX-License-Identifier: MIT
// The load's error estimate down the uniform ladders of docs/error-estimation.md:
// the sticking-ram benchmark (h = 1, 1/2, 1/4) and Hill's wedge drawing (15°, 30°;
// h = 1/4, 1/8, 1/16). The table there comes from bench/error_estimation.py.
#include "regression/benchmark_support.hpp"
#include "support/angles.hpp"
#include "support/forming_references.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace formflow::testing {
namespace {

/// The band of tests/regression/test_load_error_estimate.cpp (derived there).
constexpr double min_effectivity = 0.5, max_effectivity = 3.0;

/// `contained`: also assert p_h ± estimate ∋ exact (every rung since the safety factor
/// F_s = 1.25, docs/error-estimation.md step 5; before it three wedge rungs missed).
double effectivity(const io::Case& case_, double exact, bool contained) {
  const post::Results results = app::simulate(case_).results;
  EXPECT_TRUE(results.converged());
  EXPECT_TRUE(results.load_error.error.has_value()) << results.load_error.unavailable;
  const double error = std::abs(results.pressure.ram_reaction - exact);
  const double index = results.load_error.error.value_or(0.0) / error;
  if (contained) {
    EXPECT_LE(error, results.load_error.error.value_or(0.0)) << "p_h ± estimate holds p";
  }
  std::printf("h = %g: p_h = %.5f, estimate %.5f, error %.5f, effectivity %.3f\n", case_.mesh.size,
              results.pressure.ram_reaction, results.load_error.error.value_or(0.0), error, index);
  return index;
}

TEST(LoadErrorLadder, StickingRam) {
  for (double size : {1.0, 0.5, 0.25}) {
    io::Case case_;
    case_.process.ram = physics::RamCondition::Sticking;
    case_.material.parameters_of<physics::PiecewisePower>().alpha = 1e-4;
    case_.penalty.d = 1e-4;
    case_.mesh.size = size;
    case_.solver.load_error = solvers::LoadErrorMethod::Refined;
    const double index = effectivity(case_, 1.0 + std::numbers::pi / 2.0, true);
    EXPECT_GE(index, min_effectivity) << "h = " << size;
    EXPECT_LE(index, max_effectivity) << "h = " << size;
  }
}

TEST(LoadErrorLadder, HillWedgeDrawing) {
  for (double degrees : {15.0, 30.0})
    for (double size : {0.25, 0.125, 0.0625}) {
      io::Case case_;
      case_.process.type = physics::ProcessType::Drawing;
      const double r = hill_special_reduction(degrees * degree);
      case_.mesh.geometry = mesh::ChannelGeometry{2.0, 1.0, 1.0 - r, 2.0};
      case_.mesh.geometry.die = mesh::DieShape::Wedge;
      case_.mesh.geometry.die_angle = degrees;
      case_.mesh.size = size;
      case_.material.parameters_of<physics::PiecewisePower>().alpha = 1e-4;
      case_.solver.load_error = solvers::LoadErrorMethod::Refined;
      const double index = effectivity(case_, hill_wedge_stress(degrees * degree), true);
      EXPECT_GE(index, min_effectivity) << degrees << "°, h = " << size;
      EXPECT_LE(index, max_effectivity) << degrees << "°, h = " << size;
    }
}

} // namespace
} // namespace formflow::testing
