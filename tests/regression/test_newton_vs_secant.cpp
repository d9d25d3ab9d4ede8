// SPDX-License-Identifier: MIT
// Newton against the paper's secant iteration on the paper's cases (issue 6, "Done
// when"): the same solution to δ, and the iteration count to δ = 1e-4.
#include "regression/benchmark_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

namespace formflow {
namespace {

using Variant = std::tuple<fem::ElementKind, int, double>; // element, volumetric rule, μ

post::Results solve(const Variant& variant, solvers::NonlinearMethod method, double tolerance) {
  const auto [element, rule, mu] = variant;
  return testing::solve_benchmark([&](io::Case& c) {
    c.element = element;
    c.volumetric_points = rule;
    c.friction.mu = mu; // mesh II (the default mesh.size = 1)
    c.solver.method = method;
    c.solver.tolerance = tolerance;
    c.solver.max_iterations = 2000;
  });
}

class NewtonVsSecant : public ::testing::TestWithParam<Variant> {};

TEST_P(NewtonVsSecant, SameSolutionToDeltaAndIterationCount) {
  const double delta = 1e-4;
  const post::Results newton = solve(GetParam(), solvers::NonlinearMethod::Newton, delta);
  // The referee: the secant iteration driven far below δ. Its iterates contract
  // linearly (ρ ≈ 0.95, so stopping at change δ leaves ≈ 20δ); at 1e-8 the
  // distance to its fixed point is ~1e-6, negligible against δ.
  const post::Results reference = solve(GetParam(), solvers::NonlinearMethod::Secant, 1e-8);
  ASSERT_TRUE(newton.converged());
  ASSERT_TRUE(reference.converged());
  // Issue 6's target: at most 8 iterations to δ = 1e-4 (measured: Q2 7, 8, 8 and
  // Q1 8, 7, 7 for μ = 0, 0.1, 0.2), with the exact Jacobian (full-ε̇ coupling
  // and dτ_f by GMRES) and the first step already Newton.
  EXPECT_LE(newton.iterations, 8);
  // One factorisation per iteration plus the constant-viscosity start (no secant
  // fallback, no extra factorisation hidden in the line search), and the unsymmetric
  // part solved by GMRES (at least one iteration per step).
  EXPECT_EQ(newton.timing.counted("factorization"), newton.iterations + 1);
  EXPECT_GE(newton.timing.counted("krylov iterations"), newton.iterations);

  const VectorX& u = newton.fields.velocity;
  const VectorX& u_ref = reference.fields.velocity;
  EXPECT_LT((u - u_ref).norm() / u_ref.norm(), delta);
  // The pressure is more sensitive than ‖u‖: Newton stopped at δ must be at
  // least as close to it as the paper's method stopped at the same δ.
  const post::Results secant = solve(GetParam(), solvers::NonlinearMethod::Secant, delta);
  const double p_ref = reference.pressure.ram_reaction;
  EXPECT_LE(std::abs(newton.pressure.ram_reaction - p_ref),
            std::abs(secant.pressure.ram_reaction - p_ref));
}

// The paper's cases: Q2 with the 2×2 volumetric rule on mesh II for μ = 0, 0.1,
// 0.2, and the Q1 variant with the 1×1 rule ({Q1, P0, P1}).
INSTANTIATE_TEST_SUITE_P(PaperCasesMeshII, NewtonVsSecant,
                         ::testing::Values(Variant{fem::ElementKind::Q2, 2, 0.0},
                                           Variant{fem::ElementKind::Q2, 2, 0.1},
                                           Variant{fem::ElementKind::Q2, 2, 0.2},
                                           Variant{fem::ElementKind::Q1, 1, 0.0},
                                           Variant{fem::ElementKind::Q1, 1, 0.1},
                                           Variant{fem::ElementKind::Q1, 1, 0.2}));

} // namespace
} // namespace formflow

namespace formflow {
namespace {

// Axisymmetric Newton (hoop rate u_r/r in the residual, tangent, coupling and
// duals; r-weighted integrals): the paper's mesh II as a round billet, against
// the secant iteration driven far below δ. Measured: 7, 6, 8 iterations
// (secant to 1e-8: 310, 265, 651).
/// Newton to δ against the secant iteration driven far below δ (`reference`): at
/// most 8 plain Newton iterations (no coarse level on mesh II), one factorisation
/// each plus the constant-viscosity start (no secant fallback, none hidden in the
/// line search), GMRES on the unsymmetric part (≥ 1 iteration per step), and the
/// same velocity to δ and ram pressure to 20δ.
void expect_newton_reaches_the_secant_solution(const post::Results& newton,
                                               const post::Results& reference, double delta) {
  ASSERT_TRUE(newton.converged());
  ASSERT_TRUE(reference.converged());
  EXPECT_EQ(newton.method, "newton");
  EXPECT_LE(newton.iterations, 8);
  EXPECT_EQ(newton.timing.counted("factorization"), newton.iterations + 1);
  EXPECT_GE(newton.timing.counted("krylov iterations"), newton.iterations);
  const VectorX& u = newton.fields.velocity;
  const VectorX& u_ref = reference.fields.velocity;
  EXPECT_LT((u - u_ref).norm() / u_ref.norm(), delta);
  EXPECT_NEAR(newton.pressure.ram_reaction, reference.pressure.ram_reaction,
              20 * delta * reference.pressure.ram_reaction);
}

class AxisymmetricNewtonVsSecant : public ::testing::TestWithParam<double> {};

TEST_P(AxisymmetricNewtonVsSecant, SameSolutionToDeltaInAtMostEightIterations) {
  const double delta = 1e-4;
  auto solve = [&](solvers::NonlinearMethod method, double tolerance) {
    return testing::solve_benchmark([&](io::Case& c) {
      c.symmetry = physics::Symmetry::Axisymmetric;
      c.friction.mu = GetParam();
      c.solver.method = method;
      c.solver.tolerance = tolerance;
      c.solver.max_iterations = 2000;
    });
  };
  const post::Results newton = solve(solvers::NonlinearMethod::Newton, delta);
  const post::Results reference = solve(solvers::NonlinearMethod::Secant, 1e-8);
  expect_newton_reaches_the_secant_solution(newton, reference, delta);
}

INSTANTIATE_TEST_SUITE_P(PaperFrictionCoefficients, AxisymmetricNewtonVsSecant,
                         ::testing::Values(0.0, 0.1, 0.2));

} // namespace
} // namespace formflow

namespace formflow {
namespace {

// solver.method does not reach every formulation yet: the summary must say
// which loop actually ran rather than echo the request.
TEST(MethodReported, NamesTheLoopThatRan) {
  // h = 2.5 nests in h = 5 (the default solver.coarse_levels = 2 finds one level).
  const post::Results plane = testing::solve_benchmark([](io::Case& c) { c.mesh.size = 2.5; });
  EXPECT_EQ(plane.method, "newton from coarse meshes");
  const post::Results axisymmetric = testing::solve_benchmark([](io::Case& c) {
    c.mesh.size = 2.5;
    c.symmetry = physics::Symmetry::Axisymmetric;
    c.solver.coarse_levels = 0;
  });
  EXPECT_EQ(axisymmetric.method, "newton");
  const post::Results exact_friction = testing::solve_benchmark([](io::Case& c) {
    c.mesh.size = 2.5;
    c.friction.mu = 0.1;
    c.friction.regularization = physics::FrictionRegularization::None;
  });
  // The exact law's default under Newton: the semismooth Newton (friction.stick = "auto").
  EXPECT_EQ(exact_friction.method,
            "semismooth newton friction (exact stick at the nodes) from coarse meshes");
  const post::Results exact_augmented = testing::solve_benchmark([](io::Case& c) {
    c.mesh.size = 2.5;
    c.friction.mu = 0.1;
    c.friction.regularization = physics::FrictionRegularization::None;
    c.friction_stick = io::StickEnforcement::Augmented;
  });
  EXPECT_EQ(exact_augmented.method,
            "augmented-lagrangian friction around newton from coarse meshes");
  const post::Results exact_secant = testing::solve_benchmark([](io::Case& c) {
    c.mesh.size = 2.5;
    c.friction.mu = 0.1;
    c.friction.regularization = physics::FrictionRegularization::None;
    c.solver.method = solvers::NonlinearMethod::Secant;
  });
  EXPECT_EQ(exact_secant.method, "augmented-lagrangian friction around secant");
}

} // namespace
} // namespace formflow

namespace formflow {
namespace {

// The mixed formulation (3.7) with a discontinuous pressure condensed at d > 0
// runs Newton too (the condensation is linear in u). Measured on mesh II, μ = 0.1:
// Q2–P1disc 8, Q1–P0 7 iterations (the secant iteration to 1e-8: ~220).
using MixedVariant = std::tuple<fem::ElementKind, fem::PressureSpace>;
class MixedNewtonVsSecant : public ::testing::TestWithParam<MixedVariant> {};

TEST_P(MixedNewtonVsSecant, SameSolutionToDeltaInAtMostEightIterations) {
  const double delta = 1e-4;
  auto solve = [&](solvers::NonlinearMethod method, double tolerance) {
    return testing::solve_benchmark([&](io::Case& c) {
      c.element = std::get<0>(GetParam());
      c.formulation.type = assembly::FormulationType::Mixed;
      c.formulation.pressure = std::get<1>(GetParam());
      c.friction.mu = 0.1;
      c.solver.method = method;
      c.solver.tolerance = tolerance;
      c.solver.max_iterations = 2000;
    });
  };
  const post::Results newton = solve(solvers::NonlinearMethod::Newton, delta);
  const post::Results reference = solve(solvers::NonlinearMethod::Secant, 1e-8);
  expect_newton_reaches_the_secant_solution(newton, reference, delta);
  // The mixed pressure field is that of the secant solution (σ_H from the same
  // condensation), not the penalty problem's.
  EXPECT_NEAR(newton.pressure.mean_hydrostatic_near_ram,
              reference.pressure.mean_hydrostatic_near_ram,
              20 * delta * std::abs(reference.pressure.mean_hydrostatic_near_ram));
}

INSTANTIATE_TEST_SUITE_P(
    MeshII, MixedNewtonVsSecant,
    ::testing::Values(MixedVariant{fem::ElementKind::Q2, fem::PressureSpace::P1disc},
                      MixedVariant{fem::ElementKind::Q1, fem::PressureSpace::P0}));

// Mesh sequencing keeps the formulation: the coarse meshes solve the mixed problem
// too, and the fine solution is the mixed one (against the plain start).
TEST(MixedNewton, CoarseStartSolvesTheSameMixedProblem) {
  auto solve = [](int coarse_levels) {
    return testing::solve_benchmark([&](io::Case& c) {
      c.mesh.size = 0.5;
      c.formulation.type = assembly::FormulationType::Mixed;
      c.friction.mu = 0.1;
      c.solver.coarse_levels = coarse_levels;
      c.solver.tolerance = 1e-6;
    });
  };
  const post::Results coarse = solve(2), plain = solve(0);
  ASSERT_TRUE(coarse.converged());
  ASSERT_TRUE(plain.converged());
  EXPECT_EQ(coarse.method, "newton from coarse meshes");
  EXPECT_EQ(coarse.coarse_iterations.size(), 1u); // h = 1 (h = 2 does not nest the die)
  EXPECT_NEAR(coarse.pressure.ram_reaction, plain.pressure.ram_reaction,
              1e-5 * plain.pressure.ram_reaction);
  EXPECT_LT(coarse.iterations, plain.iterations);
}

} // namespace
} // namespace formflow
