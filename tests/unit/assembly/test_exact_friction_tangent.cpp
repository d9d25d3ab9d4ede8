// SPDX-License-Identifier: MIT
// Exact Coulomb friction in the Newton system (assembly/newton_system.cpp): the
// residual with frozen multipliers λ̂, proj_{|λ| ≤ τ_f}(λ̂ + r u_T), against the
// secant system, and its semismooth Jacobian (stick r P, slip s r (P − t̂ t̂ᵀ) in T,
// t̂ dτ_f in the coupling N) against central finite differences.
#include "support/newton_fixture.hpp"

#include <gtest/gtest.h>

#include <utility>

namespace formflow::testing {
namespace {

/// A small extrusion with exact friction (r = augmentation/d_N = 1), penalties
/// raised so the residual is smooth on the finite-difference scale.
assembly::ProblemSettings exact_friction_settings(physics::ViscousStrain strain,
                                                  physics::Symmetry symmetry) {
  assembly::ProblemSettings settings;
  settings.law = sensitive_law();
  settings.viscous_strain = strain;
  settings.symmetry = symmetry;
  settings.friction.mu = 0.2;
  settings.friction.regularization = physics::FrictionRegularization::None;
  settings.friction.augmentation = 0.1; // r = 1
  settings.penalty.d = 0.1;
  settings.penalty.d_n = 0.1;
  return settings;
}

/// The extrusion with multipliers λ̂ of the size of τ_f, chosen so that some Γ3
/// trial tractions λ̂ + r u_T lie inside the Coulomb disc and some outside.
struct ExactFrictionExtrusion : SmallExtrusion {
  assembly::FrictionMultipliers<2> multipliers;

  explicit ExactFrictionExtrusion(physics::ViscousStrain strain,
                                  physics::Symmetry symmetry = physics::Symmetry::Plane)
      : SmallExtrusion(exact_friction_settings(strain, symmetry)) {
    const auto state = problem->contact_state(u);
    const VectorX noise = random_vector(2 * static_cast<Index>(state.size()), 9);
    for (std::size_t k = 0; k < state.size(); ++k)
      multipliers.traction.push_back(state[k].friction_threshold *
                                     Point<2>(noise[2 * k], noise[2 * k + 1]));
    friction_multipliers = &multipliers;
  }
  /// Γ3 points with friction that stick / slip for the trial traction λ̂ + r u_T.
  std::pair<int, int> stick_and_slip() const {
    int stick = 0, slip = 0;
    for (const auto& point : problem->contact_state(u, &multipliers))
      if (point.friction_threshold > 0) (point.sticking ? stick : slip) += 1;
    return {stick, slip};
  }
};

// As in test_newton_tangent.cpp (fd_tolerance, support/newton_fixture.hpp): no
// point here lies within the finite-difference step of the stick/slip switch
// |t| = τ_f (both kinds are present, checked below).

TEST(ExactFrictionJacobian, TheSampleHasStickingAndSlippingPoints) {
  const ExactFrictionExtrusion extrusion(physics::ViscousStrain::Deviatoric);
  const auto [stick, slip] = extrusion.stick_and_slip();
  EXPECT_GT(stick, 0);
  EXPECT_GT(slip, 0);
}

TEST(ExactFrictionJacobian, ResidualEqualsTheSecantSystemWithTheSameMultipliers) {
  // K(u) u − F of the secant assembly (load s λ̂, penalty s r) is the residual;
  // the residual-only and the tangent path agree, and so do the reactions.
  for (const auto symmetry : {physics::Symmetry::Plane, physics::Symmetry::Axisymmetric}) {
    const ExactFrictionExtrusion extrusion(physics::ViscousStrain::Full, symmetry);
    const assembly::FormingProblem<2>& problem = *extrusion.problem;
    assembly::LinearSystem secant = problem.plan().make_system();
    problem.assemble(&extrusion.u, secant, &extrusion.multipliers);
    const VectorX free_u = extrusion.free_part(extrusion.u);
    const VectorX expected = secant.matrix.selfadjointView<Eigen::Lower>() * free_u - secant.rhs;
    const std::vector<Real> thresholds = problem.friction_thresholds(extrusion.u);
    VectorX vector_only, with_tangent;
    problem.assemble_newton(extrusion.u, thresholds, {}, vector_only, nullptr, nullptr,
                            &extrusion.multipliers);
    assembly::LinearSystem tangent = problem.plan().make_system();
    problem.assemble_newton(extrusion.u, thresholds, {}, with_tangent, &tangent, nullptr,
                            &extrusion.multipliers);
    EXPECT_LE((extrusion.free_part(vector_only) - expected).norm(), 1e-12 * expected.norm());
    EXPECT_LE((vector_only - with_tangent).norm(), 1e-12 * vector_only.norm());
    const Real reaction = problem.driven_force(secant, extrusion.u);
    EXPECT_NEAR(problem.driven_force(vector_only), reaction, 1e-12 * std::abs(reaction));
    // The multipliers matter: without them the residual differs.
    VectorX without;
    problem.assemble_newton(extrusion.u, thresholds, {}, without);
    EXPECT_GT((without - vector_only).norm(), 1e-3 * vector_only.norm());
  }
}

TEST(ExactFrictionJacobian, TangentAtFixedThresholdMatchesFiniteDifferences) {
  // Deviatoric form, τ_f frozen: T is the whole Jacobian; the coupling holds dτ_f.
  const ExactFrictionExtrusion extrusion(physics::ViscousStrain::Deviatoric);
  const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
  MatrixX symmetric;
  const MatrixX with_coupling = extrusion.jacobian(thresholds, &symmetric);
  const MatrixX fd = finite_difference_jacobian(
      [&](const VectorX& free_u) { return extrusion.free_residual(free_u, &thresholds); },
      extrusion.free_part(extrusion.u), 1e-6);
  EXPECT_LE((symmetric - fd).norm(), fd_tolerance * symmetric.norm());
  EXPECT_LE((symmetric - symmetric.transpose()).norm(), 1e-14 * symmetric.norm());
  EXPECT_GT((with_coupling - symmetric).norm(), 1e3 * fd_tolerance * symmetric.norm());
}

TEST(ExactFrictionJacobian, FullJacobianWithTheThresholdCouplingMatchesFiniteDifferences) {
  // τ_f(u) not frozen, both a-forms, plane and axisymmetric: T + N is exact.
  for (const auto symmetry : {physics::Symmetry::Plane, physics::Symmetry::Axisymmetric})
    for (const auto strain : {physics::ViscousStrain::Full, physics::ViscousStrain::Deviatoric}) {
      const ExactFrictionExtrusion extrusion(strain, symmetry);
      const auto [stick, slip] = extrusion.stick_and_slip();
      ASSERT_GT(stick, 0);
      ASSERT_GT(slip, 0);
      const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
      MatrixX symmetric;
      const MatrixX exact = extrusion.jacobian(thresholds, &symmetric);
      const MatrixX fd = finite_difference_jacobian(
          [&](const VectorX& free_u) { return extrusion.free_residual(free_u, nullptr); },
          extrusion.free_part(extrusion.u), 1e-6);
      EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
      EXPECT_GT((symmetric - fd).norm(), 1e3 * fd_tolerance * exact.norm());
    }
}

} // namespace
} // namespace formflow::testing
