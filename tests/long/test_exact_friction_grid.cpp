// SPDX-License-Identifier: MIT
// Issue 16's whole grid for exact Coulomb friction by Newton: {sliding, sticking ram}
// × h ∈ {1, 0.5, 0.25} × μ ∈ {0.05, 0.1, 0.2, 0.3, 0.5} × {Q1 1×1, Q2 2×2} ×
// {plane, axisymmetric}, at δ = 1e-4 (load against the regularised law, as in
// tests/regression/test_exact_friction_grid.cpp) and at δ = 1e-8 (no cycling at
// round-off). Run: build-test/tests/test_long --gtest_filter='*ExactFrictionFullGrid*'.
#include "support/exact_friction_grid.hpp"

#include <gtest/gtest.h>

#include <tuple>

namespace formflow::testing {
namespace {

using physics::RamCondition;
using physics::Symmetry;

using GridParameters = std::tuple<RamCondition, double, double, bool, Symmetry, double>;

class ExactFrictionFullGrid : public ::testing::TestWithParam<GridParameters> {};

TEST_P(ExactFrictionFullGrid, ConvergesInBoundedIterations) {
  const auto [ram, size, mu, q1, symmetry, tolerance] = GetParam();
  FrictionGridCase c;
  c.ram = ram;
  c.size = size;
  c.mu = mu;
  c.element = q1 ? fem::ElementKind::Q1 : fem::ElementKind::Q2;
  c.volumetric_points = q1 ? 1 : 2;
  c.symmetry = symmetry;
  // At δ = 1e-4: within 25 iterations, the load against the regularised law. At 1e-8
  // the question is convergence without cycling (measured up to 44 iterations on Q2
  // plane h = 0.25, μ = 0.5: the multiplier updates make the tail linear there). Every
  // case also asks reaction = total power (the residual's power in the stop rule).
  // Known failure (session 7, docs/friction.md "Session 7"): Q2 axisymmetric, sticking
  // ram, h = 0.25, μ = 0.5 stalls at both δ (the loop does not settle its stuck
  // tractions; the old rule stopped it with a load 7e-4 off). Q1 rows at δ = 1e-8 and
  // this test as a whole were not run in session 7. Run whole in session 11: also Q1
  // axisymmetric, sticking ram, h = 0.25, μ = 0.3 stalls at δ = 1e-8 (9 + 24 = 33, with
  // the binary before session 11's held-node rule too), which fails its δ = 1e-4 case as
  // well (that case's δ = 1e-8 reference). This loop (`friction.stick = "augmented"`) is
  // not the default; the default's grid is ExactStickFullGrid below (240 of 240).
  const bool paper_tolerance = tolerance > 1e-6;
  check_grid_case(c, tolerance, paper_tolerance, paper_tolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Grid, ExactFrictionFullGrid,
    ::testing::Combine(::testing::Values(RamCondition::Sliding, RamCondition::Sticking),
                       ::testing::Values(1.0, 0.5, 0.25),
                       ::testing::Values(0.05, 0.1, 0.2, 0.3, 0.5), ::testing::Bool(),
                       ::testing::Values(Symmetry::Plane, Symmetry::Axisymmetric),
                       ::testing::Values(1e-4, 1e-8)));

// The semismooth Newton (the exact law's default: friction.stick = "auto" resolves to
// exact stick on nodal contact points; the regularised referee on nodal points too), as
// the "Done when" asks: at δ = 1e-4 every case within 25 iterations and its load
// against the regularised law; at δ = 1e-8 convergence (no cycling at round-off), not a
// count. Measured (docs/friction.md "Session 9"): at δ = 1e-8 one case takes 26, Q2
// axisymmetric, sticking ram, h = 0.25, μ = 0.05 (8 + 18): over the 25 the issue asks at
// 1e-4, which this test does not assert at 1e-8. Run at the end of session 9: 239 of 240
// pass; the failure is plane Q1 sticking h = 0.25 μ = 0.3 at δ = 1e-4, read in session 9
// as two discrete solutions: session 10 found a false stop instead (one held node with
// |λ| = τ_f to ten digits, clipped by the Uzawa update and held again, its row out of
// balance where no test of the stop rule looks; docs/friction.md "Session 10"). The load
// check's d_T bound is right; the loop is not fixed yet.
class ExactStickFullGrid : public ::testing::TestWithParam<GridParameters> {};

TEST_P(ExactStickFullGrid, ConvergesWithin25IterationsAtThePapersTolerance) {
  const auto [ram, size, mu, q1, symmetry, tolerance] = GetParam();
  FrictionGridCase c;
  c.ram = ram;
  c.size = size;
  c.mu = mu;
  c.element = q1 ? fem::ElementKind::Q1 : fem::ElementKind::Q2;
  c.volumetric_points = q1 ? 1 : 2;
  c.symmetry = symmetry;
  c.exact_stick = true;
  const bool paper_tolerance = tolerance > 1e-6;
  check_grid_case(c, tolerance, paper_tolerance, paper_tolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Grid, ExactStickFullGrid,
    ::testing::Combine(::testing::Values(RamCondition::Sliding, RamCondition::Sticking),
                       ::testing::Values(1.0, 0.5, 0.25),
                       ::testing::Values(0.05, 0.1, 0.2, 0.3, 0.5), ::testing::Bool(),
                       ::testing::Values(Symmetry::Plane, Symmetry::Axisymmetric),
                       ::testing::Values(1e-4, 1e-8)));

} // namespace
} // namespace formflow::testing
