// SPDX-License-Identifier: MIT
// Strain rate, deviator and equivalent strain rate on flows whose answers are known by hand.
#include "formflow/physics/kinematics.hpp"

#include "formflow/fem/lagrange.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace formflow::testing {
namespace {

// All tensors here are O(1) and built from a handful of operations: 1e-14
// relative (with 1e-15 absolute for zeros) is round-off.
constexpr double rel = 1e-14, abs_zero = 1e-15;

template <int dim> Tensor2<dim> random_gradient(unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Tensor2<dim> gradient;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) gradient(i, j) = uniform(generator);
  return gradient;
}

TEST(Kinematics, SimpleShearHasEquivalentRateGammaOverRootThree) {
  // u = (γ y, 0): ε̇_xy = γ/2, ė = ε̇ (traceless), ė:ė = γ²/2, ⅔ ė:ė = γ²/3.
  const double gamma = 0.8;
  Tensor2<2> gradient;
  gradient << 0, gamma, 0, 0;
  const Tensor3 rate = physics::strain_rate<2>(gradient);
  EXPECT_TRUE(approx(rate(0, 1), gamma / 2, rel));
  EXPECT_TRUE(approx(rate(1, 0), gamma / 2, rel));
  EXPECT_EQ(rate(0, 0), 0.0);
  EXPECT_EQ(rate(2, 2), 0.0);
  EXPECT_TRUE(approx(physics::equivalent_strain_rate(rate), gamma / std::sqrt(3.0), rel));
}

TEST(Kinematics, UniaxialIncompressibleExtensionHasEquivalentRateEqualToTheAxialRate) {
  // ∇u = r diag(1, −½, −½): ė:ė = r²(1 + ¼ + ¼) = 3r²/2, ⅔ of it is r².
  const double r = 2.5;
  Tensor2<3> gradient = Tensor2<3>::Zero();
  gradient.diagonal() << r, -r / 2, -r / 2;
  const Tensor3 rate = physics::strain_rate<3>(gradient);
  EXPECT_TRUE(approx(physics::volumetric_rate(rate), 0.0, 0.0, abs_zero));
  EXPECT_TRUE(approx(physics::equivalent_strain_rate(rate), r, rel));
}

TEST(Kinematics, PlaneStrainCompressionByHand) {
  // ∇u = diag(1, −1), ε̇_zz = 0: ė:ė = 2, ε̄̇ = √(4/3) = 2/√3.
  Tensor2<2> gradient;
  gradient << 1, 0, 0, -1;
  EXPECT_TRUE(approx(physics::equivalent_strain_rate(physics::strain_rate<2>(gradient)),
                     2.0 / std::sqrt(3.0), rel));
}

TEST(Kinematics, PlaneStrainKeepsZzZeroAndTheDeviatorCarriesMinusOneThirdOfTheVolumetricRate) {
  // SPEC §1: ε̇_zz = 0 in plane strain, so ė_zz = −⅓ ε̇_V.
  Tensor2<2> gradient;
  gradient << 0.6, 0.2, -0.4, 0.3; // ε̇_V = 0.9
  const Tensor3 rate = physics::strain_rate<2>(gradient);
  EXPECT_EQ(rate(2, 2), 0.0);
  EXPECT_EQ(rate(0, 2), 0.0);
  EXPECT_EQ(rate(1, 2), 0.0);
  EXPECT_TRUE(approx(physics::volumetric_rate(rate), 0.9, rel));
  const Tensor3 dev = physics::deviator(rate);
  EXPECT_TRUE(approx(dev(2, 2), -0.3, rel));
  EXPECT_TRUE(approx(dev(0, 0), 0.6 - 0.3, rel));
  EXPECT_TRUE(approx(dev(1, 1), 0.3 - 0.3, 0.0, abs_zero));
  EXPECT_TRUE(approx(dev(0, 1), (0.2 - 0.4) / 2, rel));
  // ė:ė = 0.09 + 0 + 0.09 + 2·0.01 = 0.2 → ε̄̇ = √(0.4/3).
  EXPECT_TRUE(approx(physics::equivalent_strain_rate(rate), std::sqrt(0.4 / 3.0), rel));
}

TEST(Kinematics, DeviatorIsTracelessAndSymmetric) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Tensor3 rate2 = physics::strain_rate<2>(random_gradient<2>(seed));
    const Tensor3 rate3 = physics::strain_rate<3>(random_gradient<3>(seed));
    for (const Tensor3& rate : {rate2, rate3}) {
      const Tensor3 dev = physics::deviator(rate);
      EXPECT_TRUE(approx(dev.trace(), 0.0, 0.0, 1e-15));
      EXPECT_TRUE(approx((dev - dev.transpose()).norm(), 0.0, 0.0, abs_zero));
      EXPECT_TRUE(
          approx((rate - dev).norm(), std::abs(rate.trace()) / std::sqrt(3.0), rel, abs_zero));
    }
  }
}

TEST(Kinematics, EquivalentRateIgnoresDilatationAndRotation) {
  const Tensor2<3> gradient = random_gradient<3>(7);
  const double reference = physics::equivalent_strain_rate(physics::strain_rate<3>(gradient));
  // Adding λI (a uniform dilatation) and a skew part (a spin) changes neither ė.
  Tensor2<3> spin;
  spin << 0, 0.3, -0.2, -0.3, 0, 0.5, 0.2, -0.5, 0;
  const Tensor2<3> perturbed = gradient + 0.7 * Tensor2<3>::Identity() + spin;
  EXPECT_TRUE(
      approx(physics::equivalent_strain_rate(physics::strain_rate<3>(perturbed)), reference, rel));
  // Objectivity: R ∇u Rᵀ has the same ε̄̇.
  const double angle = 0.4;
  Tensor2<3> rotation;
  rotation << std::cos(angle), -std::sin(angle), 0, std::sin(angle), std::cos(angle), 0, 0, 0, 1;
  const Tensor2<3> rotated = rotation * gradient * rotation.transpose();
  EXPECT_TRUE(
      approx(physics::equivalent_strain_rate(physics::strain_rate<3>(rotated)), reference, 1e-13));
}

TEST(Kinematics, VelocityGradientFromNodalValuesOfALinearField) {
  // u = G x sampled at the Q1 reference nodes, with the reference gradients:
  // Σ_a u_a ⊗ ∇N_a = G for any point (∂u_i/∂x_j in row i, column j).
  Tensor2<2> g;
  g << 0.3, -1.2, 0.8, 0.5;
  VectorX values;
  Eigen::Matrix<Real, 2, Eigen::Dynamic> gradients;
  fem::tabulate_shape<2>(1, Point<2>(0.3, -0.6), values, gradients);
  Eigen::Matrix<Real, 2, Eigen::Dynamic> velocities(2, 4);
  for (int a = 0; a < 4; ++a) velocities.col(a) = g * fem::reference_node<2>(1, a);
  const Tensor2<2> result = physics::velocity_gradient<2>(velocities, gradients);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_TRUE(approx(result(i, j), g(i, j), rel, abs_zero)) << i << j;
}

} // namespace
} // namespace formflow::testing
