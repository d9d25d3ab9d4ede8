// SPDX-License-Identifier: MIT
// The Newton tangent against central finite differences of the residual: the
// viscous kernel on one distorted Q2 cell (both a-forms), the friction kernel on
// one face, and the assembled global tangent of a small extrusion with friction.
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/assembly/kernels/kernels.hpp"
#include "formflow/assembly/kernels/tangent_kernels.hpp"
#include "formflow/fem/lagrange.hpp"
#include "formflow/mesh/channel_mesh.hpp"
#include "formflow/physics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/newton_fixture.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <functional>
#include <memory>
#include <random>
#include <vector>

namespace formflow::testing {
namespace {

using Nodes2 = fem::CellValues<2>::Gradients;

/// A Q2 cell with curved map: straight outline, displaced centre node.
Nodes2 curved_q2_cell() {
  Nodes2 corners(2, 4);
  corners << 0.0, 2.0, 0.3, 2.4, //
      0.0, 0.2, 1.5, 1.9;
  Nodes2 nodes(2, 9);
  for (int a = 0; a < 9; ++a) {
    const Point<2> xi = fem::reference_node<2>(2, a);
    const double s = 0.5 * (1 + xi.x()), t = 0.5 * (1 + xi.y());
    nodes.col(a) = (1 - s) * (1 - t) * corners.col(0) + s * (1 - t) * corners.col(1) +
                   (1 - s) * t * corners.col(2) + s * t * corners.col(3);
  }
  nodes.col(4) += Point<2>(0.12, -0.07);
  return nodes;
}

/// r(u) = K_s(u) u of the a-form alone: the local viscous residual.
VectorX viscous_residual(const fem::CellValues<2>& values, const physics::FlowLaw& law,
                         physics::ViscousStrain strain, const VectorX& u) {
  const Eigen::Map<const Eigen::Matrix<Real, 2, Eigen::Dynamic>> velocities(u.data(), 2,
                                                                            values.n_nodes());
  std::vector<Real> viscosity;
  for (int q = 0; q < values.n_points(); ++q)
    viscosity.push_back(law.secant_viscosity(physics::equivalent_strain_rate(
        physics::strain_rate<2>(physics::velocity_gradient<2>(velocities, values.gradients(q))))));
  MatrixX k = MatrixX::Zero(u.size(), u.size());
  assembly::add_viscous_term<2>(values, viscosity, strain, k);
  return k * u;
}

/// Secant matrix plus the tangent correction at u, as assembly/newton_system.cpp builds it.
MatrixX viscous_tangent(const fem::CellValues<2>& values, const physics::FlowLaw& law,
                        physics::ViscousStrain strain, const VectorX& u) {
  const Eigen::Map<const Eigen::Matrix<Real, 2, Eigen::Dynamic>> velocities(u.data(), 2,
                                                                            values.n_nodes());
  std::vector<Real> viscosity, a, b;
  std::vector<Tensor3> deviators, duals;
  for (int q = 0; q < values.n_points(); ++q) {
    const Tensor3 rate =
        physics::strain_rate<2>(physics::velocity_gradient<2>(velocities, values.gradients(q)));
    const Real eps = physics::equivalent_strain_rate(rate);
    viscosity.push_back(law.secant_viscosity(eps));
    deviators.push_back(physics::deviator(rate));
    duals.push_back(viscosity.back() * deviators.back()); // the primal dual w = ν ė
    a.push_back(4.0 / 9.0 * law.yield_stress_derivative(eps) / (eps * eps));
    b.push_back(-4.0 / 9.0 / (eps * eps));
  }
  MatrixX k = MatrixX::Zero(u.size(), u.size());
  assembly::add_viscous_term<2>(values, viscosity, strain, k);
  assembly::add_viscous_tangent<2>(values, deviators, duals, a, b, k);
  return k;
}

/// Central differences of `residual` column by column, step h·(1 + ‖u‖∞).
TEST(ViscousTangent, MatchesFiniteDifferencesForTheDeviatoricForm) {
  fem::CellValues<2> values(2, fem::gauss_rule<2>(3));
  ASSERT_TRUE(values.reinit(curved_q2_cell()));
  const physics::FlowLaw law = sensitive_law();
  const auto strain = physics::ViscousStrain::Deviatoric;
  const VectorX u = random_vector(18, 7);
  const MatrixX exact = viscous_tangent(values, law, strain, u);
  const MatrixX fd = finite_difference_jacobian(
      [&](const VectorX& w) { return viscous_residual(values, law, strain, w); }, u, 1e-6);
  EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
  // The correction is not negligible: the secant matrix alone misses it clearly.
  MatrixX secant = MatrixX::Zero(18, 18);
  std::vector<Real> viscosity;
  const Eigen::Map<const Eigen::Matrix<Real, 2, Eigen::Dynamic>> velocities(u.data(), 2, 9);
  for (int q = 0; q < values.n_points(); ++q)
    viscosity.push_back(law.secant_viscosity(physics::equivalent_strain_rate(
        physics::strain_rate<2>(physics::velocity_gradient<2>(velocities, values.gradients(q))))));
  assembly::add_viscous_term<2>(values, viscosity, strain, secant);
  EXPECT_GT((secant - fd).norm(), 0.05 * fd.norm());
}

TEST(ViscousTangent, IsSymmetricPositiveDefiniteModuloRigidModesForAMonotoneLaw) {
  fem::CellValues<2> values(2, fem::gauss_rule<2>(3));
  ASSERT_TRUE(values.reinit(curved_q2_cell()));
  physics::FlowLaw law; // the paper's α = 1e-3: σ_p′ is a thousandth of σ_p/ε̄̇
  law.rate1 = 1e-8;
  for (auto strain : {physics::ViscousStrain::Full, physics::ViscousStrain::Deviatoric}) {
    const MatrixX k = viscous_tangent(values, law, strain, random_vector(18, 11));
    EXPECT_LE((k - k.transpose()).norm(), 1e-12 * k.norm());
    const VectorX lambda =
        Eigen::SelfAdjointEigenSolver<MatrixX>(k, Eigen::EigenvaluesOnly).eigenvalues();
    // Positive semi-definite, with the three rigid modes as the only zero modes.
    EXPECT_GE(lambda.minCoeff(), -1e-12 * lambda.maxCoeff());
    EXPECT_GT(lambda[3], 1e-8 * lambda.maxCoeff());
  }
}

TEST(ViscousTangent, PrimalDualFormIsPositiveSemiDefiniteForCappedDuals) {
  // Any dual w with √(⅔ w:w) ≤ σ_p(ε̄̇) keeps the symmetrised tangent PSD (the
  // reason for the cap in solvers::update_duals), here a w far from ν ė.
  fem::CellValues<2> values(2, fem::gauss_rule<2>(3));
  ASSERT_TRUE(values.reinit(curved_q2_cell()));
  physics::FlowLaw law;
  law.rate1 = 1e-8;
  const VectorX u = random_vector(18, 13);
  const Eigen::Map<const Eigen::Matrix<Real, 2, Eigen::Dynamic>> velocities(u.data(), 2, 9);
  std::vector<Real> viscosity, a, b;
  std::vector<Tensor3> deviators, duals;
  for (int q = 0; q < values.n_points(); ++q) {
    const Tensor3 rate =
        physics::strain_rate<2>(physics::velocity_gradient<2>(velocities, values.gradients(q)));
    const Real eps = physics::equivalent_strain_rate(rate);
    viscosity.push_back(law.secant_viscosity(eps));
    deviators.push_back(physics::deviator(rate));
    // A trace-free dual in another direction, scaled to the cap.
    Tensor3 w = Tensor3::Zero();
    w(0, 1) = w(1, 0) = 1.0 + 0.1 * q;
    w(0, 0) = 0.3, w(1, 1) = -0.7, w(2, 2) = 0.4;
    duals.push_back(w * (law.yield_stress(eps) / std::sqrt(2.0 / 3.0 * w.squaredNorm())));
    a.push_back(4.0 / 9.0 * law.yield_stress_derivative(eps) / (eps * eps));
    b.push_back(-4.0 / 9.0 / (eps * eps));
  }
  MatrixX k = MatrixX::Zero(18, 18);
  assembly::add_viscous_term<2>(values, viscosity, physics::ViscousStrain::Deviatoric, k);
  assembly::add_viscous_tangent<2>(values, deviators, duals, a, b, k);
  const VectorX lambda =
      Eigen::SelfAdjointEigenSolver<MatrixX>(k, Eigen::EigenvaluesOnly).eigenvalues();
  EXPECT_GE(lambda.minCoeff(), -1e-10 * lambda.maxCoeff());
}

TEST(ViscousTangent, IsExactForTheFullFormOnDivergenceFreeFields) {
  // u = (x² + 0.3y, −2xy − 0.5x) is in Q2 and divergence free, so ε̇ = ė and the
  // dropped unsymmetric term ⅓ ε̇_V(u) ε̇_V(v)(ė(u):ε̇(δu)) vanishes: the symmetric
  // tangent must then match the finite differences of the full-ε̇ residual.
  // On a curved (non-bilinear) map the Q2 interpolant of a polynomial field is
  // not the field, so take the same outline with the centre node in place.
  Nodes2 affine = curved_q2_cell();
  affine.col(4) -= Point<2>(0.12, -0.07);
  fem::CellValues<2> values(2, fem::gauss_rule<2>(3));
  ASSERT_TRUE(values.reinit(affine));
  VectorX u(18);
  for (int a = 0; a < 9; ++a) {
    const double x = affine(0, a), y = affine(1, a);
    u[2 * a] = x * x + 0.3 * y;
    u[2 * a + 1] = -2 * x * y - 0.5 * x;
  }
  const physics::FlowLaw law = sensitive_law();
  const auto strain = physics::ViscousStrain::Full;
  const MatrixX exact = viscous_tangent(values, law, strain, u);
  const MatrixX fd = finite_difference_jacobian(
      [&](const VectorX& w) { return viscous_residual(values, law, strain, w); }, u, 1e-6);
  EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
}

TEST(FrictionTangent, MatchesFiniteDifferencesAtFixedThreshold) {
  fem::FacetValues<2> values(2, fem::gauss_rule<1>(3));
  values.reinit(curved_q2_cell(), 3);
  // d_T comparable to the slip speeds, so that both the stick-like and the
  // slip-like part of τ_f u_T/√(|u_T|² + d_T²) are exercised.
  const double d_t = 0.3;
  const std::vector<Real> threshold = {0.7, 1.1, 0.4};
  auto state = [&](const VectorX& u, std::vector<Real>& weight, std::vector<Point<2>>& slip,
                   std::vector<Real>& coefficient) {
    weight.clear(), slip.clear(), coefficient.clear();
    const Eigen::Map<const Eigen::Matrix<Real, 2, Eigen::Dynamic>> velocities(u.data(), 2, 9);
    for (int q = 0; q < values.n_points(); ++q) {
      const Point<2> n = values.normal(q);
      const Point<2> v = velocities * values.shape(q);
      const Point<2> tangential = v - v.dot(n) * n;
      const double s2 = tangential.squaredNorm() + d_t * d_t;
      weight.push_back(threshold[q] / std::sqrt(s2));
      slip.push_back(tangential);
      coefficient.push_back(threshold[q] / (s2 * std::sqrt(s2)));
    }
  };
  auto residual = [&](const VectorX& u) {
    std::vector<Real> weight, coefficient;
    std::vector<Point<2>> slip;
    state(u, weight, slip, coefficient);
    MatrixX k = MatrixX::Zero(18, 18);
    assembly::add_friction_term<2>(values, weight, k);
    return VectorX(k * u);
  };
  const VectorX u = 0.4 * random_vector(18, 3);
  std::vector<Real> weight, coefficient;
  std::vector<Point<2>> slip;
  state(u, weight, slip, coefficient);
  MatrixX exact = MatrixX::Zero(18, 18);
  assembly::add_friction_term<2>(values, weight, exact);
  assembly::add_friction_tangent<2>(values, slip, slip, coefficient, exact);
  const MatrixX fd = finite_difference_jacobian(residual, u, 1e-6);
  EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
  EXPECT_LE((exact - exact.transpose()).norm(), 1e-14 * exact.norm());
}

/// The regularised-friction extrusion: friction on Γ3 (μ = 0.2) with d_T and the
/// penalties raised so that the residual is smooth on the finite-difference scale.
assembly::ProblemSettings
regularised_extrusion(physics::ViscousStrain strain,
                      physics::Symmetry symmetry = physics::Symmetry::Plane,
                      assembly::ContactNormals normals = assembly::ContactNormals::Faces) {
  assembly::ProblemSettings settings;
  settings.law = sensitive_law();
  settings.viscous_strain = strain;
  settings.symmetry = symmetry;
  settings.contact.normals = normals;
  settings.friction.mu = 0.2;
  settings.friction.d_t = 0.05;
  settings.penalty.d = 0.1;
  settings.penalty.d_n = 0.1;
  return settings;
}

TEST(NewtonSystem, GlobalTangentMatchesFiniteDifferencesOfTheResidual) {
  // With τ_f frozen and the deviatoric form the symmetric tangent T is the whole
  // Jacobian; the coupling then holds only dτ_f, which the frozen residual lacks.
  const SmallExtrusion extrusion(regularised_extrusion(physics::ViscousStrain::Deviatoric));
  const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
  ASSERT_GT(*std::max_element(thresholds.begin(), thresholds.end()), 0.0);
  MatrixX symmetric;
  const MatrixX with_coupling = extrusion.jacobian(thresholds, &symmetric);
  const MatrixX fd = finite_difference_jacobian(
      [&](const VectorX& free_u) { return extrusion.free_residual(free_u, &thresholds); },
      extrusion.free_part(extrusion.u), 1e-6);
  EXPECT_LE((symmetric - fd).norm(), fd_tolerance * symmetric.norm());
  EXPECT_GT((with_coupling - symmetric).norm(), 1e3 * fd_tolerance * symmetric.norm());
}

TEST(NewtonSystem, CouplingTransposeIsTheCouplingsTranspose) {
  // The adjoint of the load (post/load_error_estimate.hpp) applies Nᵀ matrix free:
  // the full form's cell part and Coulomb's dτ_f through the mollified σ̄_N.
  // Column by column against apply_coupling over the free dofs: the same products
  // summed in another order, so they agree to round-off, ε times the terms per
  // entry (at most a few hundred here) relative to ‖N‖: 1e-12.
  for (const physics::ViscousStrain strain :
       {physics::ViscousStrain::Deviatoric, physics::ViscousStrain::Full}) {
    const SmallExtrusion extrusion(regularised_extrusion(strain));
    const assembly::ScatterPlan& plan = extrusion.problem->plan();
    assembly::LinearSystem tangent = plan.make_system();
    assembly::UnsymmetricTangent<2> coupling;
    VectorX force;
    extrusion.problem->assemble_newton(extrusion.u,
                                       extrusion.problem->friction_thresholds(extrusion.u), {},
                                       force, &tangent, &coupling);
    ASSERT_TRUE(coupling.has_friction);
    const Index n = plan.n_free();
    MatrixX forward(n, n), transposed(n, n);
    for (Index k = 0; k < n; ++k) {
      VectorX column = VectorX::Zero(n);
      extrusion.problem->apply_coupling(coupling, VectorX::Unit(n, k), column);
      forward.col(k) = column;
      VectorX full = VectorX::Zero(plan.n_dofs());
      extrusion.problem->apply_coupling_transpose(
          coupling, plan.expand(VectorX::Unit(n, k), VectorX::Zero(plan.n_dofs())), full);
      transposed.col(k) = extrusion.free_part(full);
    }
    ASSERT_GT(forward.norm(), 0.0);
    EXPECT_LE((transposed - forward.transpose()).norm(), 1e-12 * forward.norm());
  }
}

TEST(NewtonSystem, FullFormJacobianWithItsUnsymmetricCouplingMatchesFiniteDifferences) {
  // The paper's full-ε̇ a-form and τ_f(u) not frozen: the symmetric tangent alone
  // misses ⅔ ν′ dε̄̇ ⅓ ε̇_V ε̇_V and dτ_f; with the coupling the Jacobian is exact.
  const SmallExtrusion extrusion(regularised_extrusion(physics::ViscousStrain::Full));
  const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
  MatrixX symmetric;
  const MatrixX exact = extrusion.jacobian(thresholds, &symmetric);
  const MatrixX fd = finite_difference_jacobian(
      [&](const VectorX& free_u) { return extrusion.free_residual(free_u, nullptr); },
      extrusion.free_part(extrusion.u), 1e-6);
  EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
  EXPECT_GT((symmetric - fd).norm(), 1e3 * fd_tolerance * exact.norm());
  EXPECT_GT((exact - exact.transpose()).norm(), 1e-6 * exact.norm());
}

TEST(NewtonSystem, AxisymmetricJacobianMatchesFiniteDifferences) {
  // Axisymmetry (y = r): hoop rate u_r/r in ε̇, ε̇_V and the duals, r-weighted
  // integrals; both a-forms, τ_f(u) not frozen.
  for (const auto strain : {physics::ViscousStrain::Full, physics::ViscousStrain::Deviatoric}) {
    const SmallExtrusion extrusion(regularised_extrusion(strain, physics::Symmetry::Axisymmetric));
    const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
    ASSERT_GT(*std::max_element(thresholds.begin(), thresholds.end()), 0.0);
    MatrixX symmetric;
    const MatrixX exact = extrusion.jacobian(thresholds, &symmetric);
    const MatrixX fd = finite_difference_jacobian(
        [&](const VectorX& free_u) { return extrusion.free_residual(free_u, nullptr); },
        extrusion.free_part(extrusion.u), 1e-6);
    EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
    EXPECT_GT((symmetric - fd).norm(), 1e3 * fd_tolerance * exact.norm());
  }
}

TEST(NewtonSystem, JacobianWithNodalContactNormalsMatchesFiniteDifferences) {
  // contact.normals = "nodes": Γ3 evaluated at the face nodes with averaged normals,
  // in the residual, the friction tangent and dτ_f alike.
  const SmallExtrusion extrusion(regularised_extrusion(
      physics::ViscousStrain::Full, physics::Symmetry::Plane, assembly::ContactNormals::Nodes));
  const std::vector<Real> thresholds = extrusion.problem->friction_thresholds(extrusion.u);
  ASSERT_GT(*std::max_element(thresholds.begin(), thresholds.end()), 0.0);
  const MatrixX exact = extrusion.jacobian(thresholds);
  const MatrixX fd = finite_difference_jacobian(
      [&](const VectorX& free_u) { return extrusion.free_residual(free_u, nullptr); },
      extrusion.free_part(extrusion.u), 1e-6);
  EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());
  // The residual-only path agrees with the secant system there too.
  assembly::LinearSystem secant = extrusion.problem->plan().make_system();
  extrusion.problem->assemble(&extrusion.u, secant);
  const VectorX free_u = extrusion.free_part(extrusion.u);
  const VectorX expected = secant.matrix.selfadjointView<Eigen::Lower>() * free_u - secant.rhs;
  EXPECT_LE((extrusion.free_residual(free_u, &thresholds) - expected).norm(),
            1e-12 * expected.norm());
}

TEST(NewtonSystem, MixedCondensedPressureJacobianAndResidualMatchTheSecantSystem) {
  // The mixed formulation with a discontinuous pressure condensed at d > 0: the
  // cell term (1/d) Bᵀ M⁻¹ B replaces the volumetric penalty in the residual (both
  // paths) and, being linear in u, enters the tangent unchanged.
  for (const auto space : {fem::PressureSpace::P1disc, fem::PressureSpace::P0}) {
    SmallExtrusion extrusion(regularised_extrusion(physics::ViscousStrain::Full));
    extrusion.attach_mixed_pressure(space);
    const assembly::FormingProblem<2>& problem = *extrusion.problem;
    const std::vector<Real> thresholds = problem.friction_thresholds(extrusion.u);
    const MatrixX exact = extrusion.jacobian(thresholds);
    const MatrixX fd = finite_difference_jacobian(
        [&](const VectorX& free_u) { return extrusion.free_residual(free_u, nullptr); },
        extrusion.free_part(extrusion.u), 1e-6);
    EXPECT_LE((exact - fd).norm(), fd_tolerance * exact.norm());

    assembly::LinearSystem secant = problem.plan().make_system();
    problem.assemble(&extrusion.u, secant);
    const VectorX free_u = extrusion.free_part(extrusion.u);
    const VectorX expected = secant.matrix.selfadjointView<Eigen::Lower>() * free_u - secant.rhs;
    VectorX with_tangent;
    assembly::LinearSystem tangent = problem.plan().make_system();
    problem.assemble_newton(extrusion.u, thresholds, {}, with_tangent, &tangent);
    EXPECT_LE((extrusion.free_residual(free_u, &thresholds) - expected).norm(),
              1e-12 * expected.norm());
    EXPECT_LE((extrusion.free_part(with_tangent) - expected).norm(), 1e-12 * expected.norm());
    // Against the penalty problem's residual: the pressure term really changed.
    const SmallExtrusion penalty(regularised_extrusion(physics::ViscousStrain::Full));
    EXPECT_GT((penalty.free_residual(free_u, &thresholds) - expected).norm(),
              1e-3 * expected.norm());
  }
}

TEST(NewtonSystem, ResidualOnlyAssemblyEqualsTheSecantSystemAppliedToTheVelocity) {
  // Three routes to K(u)u − F: the secant assembly with τ_f(u), assemble_newton's
  // matrix-free residual, and its residual from the local secant matrices. The
  // prescribed rows give the reaction, so the driven force must agree too.
  for (const auto symmetry : {physics::Symmetry::Plane, physics::Symmetry::Axisymmetric})
    for (const auto strain : {physics::ViscousStrain::Full, physics::ViscousStrain::Deviatoric}) {
      const SmallExtrusion extrusion(regularised_extrusion(strain, symmetry));
      const assembly::FormingProblem<2>& problem = *extrusion.problem;
      const std::vector<Real> thresholds = problem.friction_thresholds(extrusion.u);
      assembly::LinearSystem secant = problem.plan().make_system();
      problem.assemble(&extrusion.u, secant);
      const VectorX free_u = extrusion.free_part(extrusion.u);
      const VectorX expected = secant.matrix.selfadjointView<Eigen::Lower>() * free_u - secant.rhs;

      VectorX vector_only, with_tangent;
      problem.assemble_newton(extrusion.u, thresholds, {}, vector_only);
      assembly::LinearSystem tangent = problem.plan().make_system();
      problem.assemble_newton(extrusion.u, thresholds, {}, with_tangent, &tangent);
      EXPECT_LE((extrusion.free_part(vector_only) - expected).norm(), 1e-12 * expected.norm());
      EXPECT_LE((vector_only - with_tangent).norm(), 1e-12 * vector_only.norm());
      const Real reaction = problem.driven_force(secant, extrusion.u);
      EXPECT_NEAR(problem.driven_force(vector_only), reaction, 1e-12 * std::abs(reaction));
      EXPECT_GT(std::abs(reaction), 0.0);
    }
}

} // namespace
} // namespace formflow::testing
