// SPDX-License-Identifier: MIT
// Drawing and extrusion through wedge/conical dies against slip-line, ideal-work
// and upper-bound references (docs/validation.md), on coarse meshes.
#include "benchmark_support.hpp"
#include "support/angles.hpp"
#include "support/approx.hpp"
#include "support/forming_references.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace formflow::testing {
namespace {

/// Unit entry half height, entry part 1 and exit part 2 long, Q2, nearly rate-insensitive.
io::Case wedge_case(physics::ProcessType type, double degrees, double exit_half_height,
                    double size) {
  io::Case case_;
  case_.process.type = type;
  case_.mesh.geometry = mesh::ChannelGeometry{1.0, 1.0, exit_half_height, 2.0};
  case_.mesh.geometry.die = mesh::DieShape::Wedge;
  case_.mesh.geometry.die_angle = degrees;
  case_.mesh.size = size;
  case_.material.parameters_of<physics::PiecewisePower>().alpha = 1e-4;
  case_.solver.max_iterations = 2000;
  return case_;
}

double load(const post::Results& results) {
  return results.pressure.ram_reaction;
}

TEST(DrawingDies, PlaneWedgeDrawingApproachesHillsSlipLineSolution) {
  const double alpha = 15 * degree, r = hill_special_reduction(alpha);
  const io::Case case_ = wedge_case(physics::ProcessType::Drawing, 15, 1 - r, 0.125);
  const post::Results results = app::simulate(case_).results;
  ASSERT_TRUE(results.converged());
  const double ours = load(results);
  // Exact rigid-plastic value 2k(1+α)r = 0.8608; the ideal work 0.8343 is a
  // strict lower bound and the radial-flow field 1.100 an upper bound.
  EXPECT_GT(ours, plane_ideal(r));
  EXPECT_LT(ours, plane_radial_upper_bound(alpha, r));
  // The discrete solution converges to the slip-line value from above, O(h):
  // +5.5 % on these 8 rows, +3.0 % on 16 (docs/validation.md, ladder). The
  // penalty d = 1e-3 can lower it by O(d) = 0.1 %. So: within [−0.1 %, +7 %];
  // a formulation error of the size of the redundant work (the ideal work is
  // 3 % below) or of the bound (28 % above) falls outside.
  const double exact = hill_wedge_stress(alpha);
  EXPECT_GT(ours, exact * (1 - 1e-3));
  EXPECT_LT(ours, exact * 1.07);
  // Power balance: the reaction equals the total discrete power.
  EXPECT_TRUE(approx(results.pressure.total_power, ours, 1e-3));
}

TEST(DrawingDies, AxisymmetricWireDrawingLiesBetweenIdealWorkAndAvitzur) {
  const double alpha = 10 * degree, r = 0.2;
  io::Case case_ = wedge_case(physics::ProcessType::Drawing, 10, std::sqrt(1 - r), 0.125);
  case_.symmetry = physics::Symmetry::Axisymmetric;
  const post::Results results = app::simulate(case_).results;
  ASSERT_TRUE(results.converged());
  const double ours = load(results);
  EXPECT_GT(ours, axisymmetric_ideal(r));
  EXPECT_LT(ours, avitzur_upper_bound(alpha, r));
  EXPECT_TRUE(approx(results.pressure.total_power, ours, 1e-3));
}

} // namespace
} // namespace formflow::testing
