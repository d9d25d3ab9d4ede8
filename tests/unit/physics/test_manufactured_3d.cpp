// SPDX-License-Identifier: MIT
// The 3D manufactured field: divergence-free, derivatives and body force against finite
// differences, a strain rate that never vanishes on the cube.
#include "formflow/physics/kinematics.hpp"
#include "formflow/physics/manufactured_3d.hpp"

#include <gtest/gtest.h>

namespace formflow::physics {
namespace {

const Point<3> solid_sample_points[] = {Point<3>(0.3, 0.7, 0.2), Point<3>(0.81, 0.12, 0.66),
                                        Point<3>(0.55, 0.45, 0.93)};

TEST(ManufacturedField3d, IsDivergenceFreeWithConsistentDerivatives) {
  const VectorPotentialField field = VectorPotentialField::of(ManufacturedSolution::Smooth);
  const Real step = 1e-6;
  for (const Point<3>& x : solid_sample_points) {
    const Tensor2<3> gradient = field.gradient(x);
    EXPECT_NEAR(gradient.trace(), 0.0, 1e-13);
    const auto hessian = field.hessians(x);
    for (int k = 0; k < 3; ++k) {
      const Point<3> dx = step * Point<3>::Unit(k);
      // Central differences: error O(step²) times third derivatives (~a·π³ ≈ 1.6),
      // plus rounding ε·|u|/step ≈ 1e-10.
      const Point<3> du = (field.velocity(x + dx) - field.velocity(x - dx)) / (2 * step);
      const Tensor2<3> dgrad = (field.gradient(x + dx) - field.gradient(x - dx)) / (2 * step);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(du[i], gradient(i, k), 1e-8);
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(dgrad(i, j), hessian[i](j, k), 1e-7);
      }
    }
  }
}

/// τ = ⅔ ν(ε̄̇) ε̇ of the field at x.
Tensor2<3> viscous_stress(const FlowLaw& law, const VectorPotentialField& field,
                          const Point<3>& x) {
  const Tensor3 rate = strain_rate<3>(field.gradient(x));
  return 2.0 / 3.0 * law.secant_viscosity(equivalent_strain_rate(rate)) * rate;
}

TEST(ManufacturedField3d, BodyForceIsMinusDivergenceOfViscousStress) {
  const VectorPotentialField field = VectorPotentialField::of(ManufacturedSolution::Smooth);
  FlowLaw nonlinear; // the paper's law (5.4)
  FlowLaw strongly_nonlinear;
  strongly_nonlinear.as<physics::PiecewisePower>().alpha = 0.2;
  const Real step = 1e-5;
  for (const FlowLaw& law : {nonlinear, strongly_nonlinear})
    for (const Point<3>& x : solid_sample_points) {
      Point<3> divergence = Point<3>::Zero();
      for (int k = 0; k < 3; ++k) {
        const Point<3> dx = step * Point<3>::Unit(k);
        divergence +=
            ((viscous_stress(law, field, x + dx) - viscous_stress(law, field, x - dx)) / (2 * step))
                .col(k);
      }
      const Point<3> force = manufactured_body_force(law, field, x);
      // Central differences of τ (entries ~1): error ~ step²·τ‴ + ε|τ|/step ≈ 1e-10.
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(force[i], -divergence[i], 1e-7)
            << "alpha " << law.as<physics::PiecewisePower>().alpha;
      // Not trivially zero: the vortex loads the cube.
      EXPECT_GT(force.norm(), 1e-3);
    }
}

TEST(ManufacturedField3d, StrainRateStaysAwayFromZeroOnTheCube) {
  // The header's bound: ‖ε̇‖_F ≥ c√(3/2) − 3·2ak = 1.2247 − 0.9425 > 0.28, so
  // ε̄̇ = √(2/3)‖ε̇‖_F ≥ 0.23 everywhere; checked (≥ 0.2) on a lattice of the cube.
  const VectorPotentialField field = VectorPotentialField::of(ManufacturedSolution::Smooth);
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
      for (int k = 0; k <= 10; ++k) {
        const Point<3> x(i / 10.0, j / 10.0, k / 10.0);
        EXPECT_GE(equivalent_strain_rate(strain_rate<3>(field.gradient(x))), 0.2);
      }
}

} // namespace
} // namespace formflow::physics
