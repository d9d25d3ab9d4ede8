// SPDX-License-Identifier: MIT
// Nonlocal contact-pressure average and the regularised Coulomb threshold and weight.
#include "formflow/physics/friction.hpp"

#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace formflow::testing {
namespace {

// Weighted means of ≤ 4 O(10) values: round-off is ~1e-15 relative.
constexpr double roundoff = 1e-14;

/// Points on a line y = 0.5 (2 × n), so distances are |Δx|.
MatrixX points_on_a_line(const std::vector<double>& x) {
  MatrixX points(2, static_cast<Index>(x.size()));
  for (std::size_t k = 0; k < x.size(); ++k) points.col(static_cast<Index>(k)) << x[k], 0.5;
  return points;
}

TEST(NonlocalAverage, RadiusZeroIsTheIdentity) {
  // Two coincident points: only i itself counts when h = 0 (local pressure).
  const MatrixX points = points_on_a_line({0.0, 0.0, 1.0, 2.5});
  const physics::NonlocalAverage average(points, {1.0, 2.0, 3.0, 4.0}, 0.0);
  ASSERT_EQ(average.size(), 4);
  const std::vector<Real> pressure = {3.0, -1.0, 7.5, 0.25};
  std::vector<Real> averaged;
  average.apply(pressure, averaged);
  ASSERT_EQ(averaged.size(), pressure.size());
  for (std::size_t k = 0; k < pressure.size(); ++k) EXPECT_EQ(averaged[k], pressure[k]);
}

TEST(NonlocalAverage, ConstantFieldIsPreservedForAnyRadius) {
  MatrixX points(2, 5);
  points << 0.0, 0.3, 1.1, 1.2, 4.0, //
      0.0, 0.4, -0.2, 0.9, 1.0;
  const std::vector<Real> weights = {0.5, 1.5, 0.25, 2.0, 1.0};
  for (double radius : {0.0, 0.5, 1.0, 3.0, 100.0}) {
    const physics::NonlocalAverage average(points, weights, radius);
    std::vector<Real> averaged;
    average.apply(std::vector<Real>(5, 2.75), averaged);
    for (double value : averaged) EXPECT_TRUE(approx(value, 2.75, roundoff)) << "radius " << radius;
  }
}

TEST(NonlocalAverage, WeightedMeanOverNeighboursWithinTheRadiusByHand) {
  // x = 0, 1, 1.9, 3.5 with weights 1, 2, 3, 4 and pressures 10, 20, 30, 40;
  // radius 1.2 (strictly less than):
  //   point 0 sees {0, 1}:     (1·10 + 2·20)/3         = 50/3
  //   point 1 sees {0, 1, 2}:  (10 + 40 + 90)/6        = 70/3
  //   point 2 sees {1, 2}:     (40 + 90)/5             = 26
  //   point 3 sees only itself                         = 40
  const physics::NonlocalAverage average(points_on_a_line({0.0, 1.0, 1.9, 3.5}), {1, 2, 3, 4}, 1.2);
  std::vector<Real> averaged;
  average.apply({10, 20, 30, 40}, averaged);
  EXPECT_TRUE(approx(averaged[0], 50.0 / 3.0, roundoff));
  EXPECT_TRUE(approx(averaged[1], 70.0 / 3.0, roundoff));
  EXPECT_TRUE(approx(averaged[2], 26.0, roundoff));
  EXPECT_TRUE(approx(averaged[3], 40.0, roundoff));
}

TEST(NonlocalAverage, UsesEuclideanDistanceInThePlane) {
  // (0,0), (3,4)/10 at distance 0.5, (0.6,0) at 0.6 from the first and
  // |(0.3,−0.4)| = 0.5 from the second. Radius 0.55 pairs 0–1 and 1–2 only.
  MatrixX points(2, 3);
  points << 0.0, 0.3, 0.6, //
      0.0, 0.4, 0.0;
  const physics::NonlocalAverage average(points, {1.0, 1.0, 2.0}, 0.55);
  std::vector<Real> averaged;
  average.apply({0.0, 3.0, 6.0}, averaged);
  EXPECT_TRUE(approx(averaged[0], 1.5, roundoff));                      // (0 + 3)/2
  EXPECT_TRUE(approx(averaged[1], (0.0 + 3.0 + 12.0) / 4.0, roundoff)); // all three
  EXPECT_TRUE(approx(averaged[2], (3.0 + 12.0) / 3.0, roundoff));       // {1, 2}
}

TEST(NonlocalAverage, NeighbourExactlyAtTheRadiusIsExcluded) {
  // Γ_h(x) = {y : |x − y| < h}: a point at distance exactly h does not count.
  const physics::NonlocalAverage average(points_on_a_line({0.0, 1.0}), {1.0, 1.0}, 1.0);
  std::vector<Real> averaged;
  average.apply({2.0, 8.0}, averaged);
  EXPECT_EQ(averaged[0], 2.0);
  EXPECT_EQ(averaged[1], 8.0);
}

TEST(FrictionThreshold, IsMuTimesMeanPressureAndZeroUnderTension) {
  EXPECT_TRUE(approx(physics::CoulombThreshold{0.2}.at({3.5, 0.0}).value, 0.7, roundoff));
  EXPECT_EQ(physics::CoulombThreshold{0.2}.at({0.0, 0.0}).value, 0.0);
  EXPECT_EQ(physics::CoulombThreshold{0.2}.at({-4.0, 0.0}).value,
            0.0); // tensile: no contact, no friction
  EXPECT_EQ(physics::CoulombThreshold{0.0}.at({5.0, 0.0}).value, 0.0);
}

TEST(FrictionWeight, IsThresholdOverRegularisedSlipSpeed) {
  // √(3² + 4²) = 5.
  EXPECT_TRUE(approx(physics::friction_weight(2.0, 3.0, 4.0), 0.4, roundoff));
  // At rest the weight is τ_f/d_T: large but finite.
  EXPECT_TRUE(approx(physics::friction_weight(1.5, 0.0, 1e-6), 1.5e6, roundoff));
  // Sliding fast compared with d_T: the friction stress weight·|u_T| → τ_f.
  // The relative deviation is ½(d_T/|u_T|)² = 5e-13 for these numbers.
  EXPECT_TRUE(approx(physics::friction_weight(0.8, 1e-3, 1e-9) * 1e-3, 0.8, 1e-11));
  // And never above τ_f.
  for (double slip : {1e-8, 1e-4, 1.0, 1e4})
    EXPECT_LE(physics::friction_weight(0.8, slip, 1e-6) * slip, 0.8);
}

TEST(FrictionWeight, TangentialStressIsTheDerivativeOfTheRegularisedPotential) {
  // j_dT = τ_f √(s² + d_T²) has dj/ds = τ_f s/√(s² + d_T²) = weight·s (eq. 3.14–3.15).
  // Central difference with step 1e-7 on a smooth O(1) function: error ~1e-9.
  const double tau = 1.3, d_t = 0.05, h = 1e-7;
  auto potential = [&](double s) { return tau * std::sqrt(s * s + d_t * d_t); };
  for (double slip : {0.0, 0.01, 0.05, 0.3, 2.0}) {
    const double difference = (potential(slip + h) - potential(slip - h)) / (2 * h);
    EXPECT_TRUE(approx(physics::friction_weight(tau, slip, d_t) * slip, difference, 1e-7, 1e-8))
        << slip;
  }
}

} // namespace
} // namespace formflow::testing
