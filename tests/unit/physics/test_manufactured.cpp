// SPDX-License-Identifier: MIT
// The manufactured fields: divergence-free, derivatives and body force against finite differences.
#include "formflow/physics/kinematics.hpp"
#include "formflow/physics/manufactured.hpp"
#include "support/approx.hpp"

#include <gtest/gtest.h>

namespace formflow::physics {
namespace {

const Point<2> plane_sample_points[] = {Point<2>(0.3, 0.7), Point<2>(0.81, 0.12),
                                        Point<2>(0.55, 0.45)};

TEST(ManufacturedField, IsDivergenceFreeWithConsistentDerivatives) {
  const StreamFunctionField field = StreamFunctionField::of(ManufacturedSolution::Smooth);
  const Real step = 1e-6;
  for (const Point<2>& x : plane_sample_points) {
    const Tensor2<2> gradient = field.gradient(x);
    EXPECT_NEAR(gradient.trace(), 0.0, 1e-13);
    const auto hessian = field.hessians(x);
    for (int k = 0; k < 2; ++k) {
      const Point<2> dx = step * Point<2>::Unit(k);
      // Central differences: error O(step²) ≈ 1e-12 times the third derivatives (~π³).
      const Point<2> du = (field.velocity(x + dx) - field.velocity(x - dx)) / (2 * step);
      const Tensor2<2> dgrad = (field.gradient(x + dx) - field.gradient(x - dx)) / (2 * step);
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(du[i], gradient(i, k), 1e-8);
        for (int j = 0; j < 2; ++j) EXPECT_NEAR(dgrad(i, j), hessian[i](j, k), 1e-7);
      }
    }
  }
}

/// τ = ⅔ ν(ε̄̇) ε̇ of the field at x (2×2 block).
Tensor2<2> viscous_stress(const FlowLaw& law, const StreamFunctionField& field, const Point<2>& x) {
  const Tensor3 rate = strain_rate<2>(field.gradient(x));
  return 2.0 / 3.0 * law.secant_viscosity(equivalent_strain_rate(rate)) *
         rate.topLeftCorner<2, 2>();
}

TEST(ManufacturedField, BodyForceIsMinusDivergenceOfViscousStress) {
  const StreamFunctionField field = StreamFunctionField::of(ManufacturedSolution::Smooth);
  FlowLaw nonlinear; // the paper's law (5.4)
  FlowLaw strongly_nonlinear;
  strongly_nonlinear.as<physics::PiecewisePower>().alpha = 0.2;
  FlowLaw constant;
  constant.as<physics::PiecewisePower>().alpha = 1.0; // σ_p = A ε̄̇: constant viscosity A
  const Real step = 1e-5;
  for (const FlowLaw& law : {nonlinear, strongly_nonlinear, constant})
    for (const Point<2>& x : plane_sample_points) {
      Point<2> divergence = Point<2>::Zero();
      for (int k = 0; k < 2; ++k) {
        const Point<2> dx = step * Point<2>::Unit(k);
        divergence +=
            ((viscous_stress(law, field, x + dx) - viscous_stress(law, field, x - dx)) / (2 * step))
                .col(k);
      }
      const Point<2> force = manufactured_body_force(law, field, x);
      // Central differences of τ (entries up to ~40): error ~ step²·τ‴ ≈ 1e-7.
      for (int i = 0; i < 2; ++i)
        EXPECT_NEAR(force[i], -divergence[i], 1e-6)
            << "alpha " << law.as<physics::PiecewisePower>().alpha;
    }
}

TEST(ManufacturedField, ExtensionFieldIsLinearWithZeroBodyForce) {
  const StreamFunctionField field = StreamFunctionField::of(ManufacturedSolution::Extension);
  const FlowLaw law;
  for (const Point<2>& x : plane_sample_points) {
    EXPECT_NEAR(field.velocity(x).x(), x.x(), 1e-15);
    EXPECT_NEAR(field.velocity(x).y(), -x.y(), 1e-15);
    EXPECT_NEAR(manufactured_body_force(law, field, x).norm(), 0.0, 1e-12);
  }
}

} // namespace
} // namespace formflow::physics
