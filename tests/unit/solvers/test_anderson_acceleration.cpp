// SPDX-License-Identifier: MIT
// Anderson acceleration on linear fixed-point maps G(x) = A x + b with a known spectrum
// and answer, and its safeguards on hand-made pairs.
#include "formflow/solvers/anderson_acceleration.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/QR>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace formflow::solvers {
namespace {

/// G(x) = A x + b, A symmetric with the given eigenvalues in an orthonormal basis that
/// mixes every coordinate (Q from the QR of a fixed full matrix), so that no eigenvector
/// is a coordinate axis.
struct AndersonLinearMap {
  MatrixX a;
  VectorX b;
  explicit AndersonLinearMap(const std::vector<Real>& eigenvalues) {
    const auto n = static_cast<Index>(eigenvalues.size());
    MatrixX full(n, n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j) full(i, j) = std::cos(1.0 + 3.0 * i + 7.0 * j * j);
    const MatrixX q = Eigen::HouseholderQR<MatrixX>(full).householderQ();
    VectorX lambda(n);
    for (Index i = 0; i < n; ++i) lambda[i] = eigenvalues[static_cast<std::size_t>(i)];
    a = q * lambda.asDiagonal() * q.transpose();
    b = VectorX::LinSpaced(n, 1.0, 2.0);
  }
  VectorX operator()(const VectorX& x) const { return a * x + b; }
  VectorX fixed_point() const {
    return (MatrixX::Identity(a.rows(), a.cols()) - a).partialPivLu().solve(b);
  }
};

struct AndersonRun {
  int images = 0; ///< evaluations of G until the change fell below the tolerance
  VectorX last_image;
};

/// The secant loop's stop on this map: x ↦ G(x) until ‖G(x) − x‖ < tol ‖G(x)‖, from x = 0;
/// `depth` 0 is the plain iteration.
AndersonRun iterate_linear_map(const AndersonLinearMap& map, int depth, Real tolerance) {
  AndersonRun run;
  std::optional<AndersonAcceleration> anderson;
  if (depth > 0) anderson.emplace(depth);
  VectorX x = VectorX::Zero(map.b.size());
  for (run.images = 1; run.images < 10000; ++run.images) {
    run.last_image = map(x);
    if ((run.last_image - x).norm() < tolerance * run.last_image.norm()) break;
    x = anderson ? anderson->next(x, run.last_image) : run.last_image;
  }
  return run;
}

/// The change an exact Anderson iterate can still show, per difference column mixed:
/// the mixing weights carry a relative error up to cond · ε with cond ≤
/// anderson_max_condition (beyond it the history is dropped), each column's share of the
/// mixed iterate that times ‖x‖ (the images' differences are bounded by ‖x‖ here), and
/// ‖G(x) − x‖ = ‖(A − I) e‖ ≤ 2 ‖e‖ for eigenvalues in [0, 1).
const Real anderson_roundoff_change =
    2 * anderson_max_condition * std::numeric_limits<Real>::epsilon();

/// Walker & Ni: Anderson without truncation on a linear map is GMRES on (I − A) x = b
/// (x_{k+1} = G(x_k^GMRES)); GMRES on dimension n is exact after n steps, so the
/// iterate made from n + 1 images is the fixed point and the (n + 2)-th image confirms it.
/// The plain iteration needs of the order of log(tol)/log(ρ) steps, ρ = 0.9 (118 here).
TEST(AndersonAcceleration, LinearMapOfDimensionAtMostTheDepthConvergesInDimensionPlusTwoImages) {
  const std::vector<Real> eigenvalues = {0.1, 0.35, 0.6, 0.9};
  const AndersonLinearMap map(eigenvalues);
  const int n = static_cast<int>(eigenvalues.size());
  const Real rho = 0.9;
  const Real tolerance = (n + 1) * anderson_roundoff_change; // n + 1 columns at most
  const AndersonRun plain = iterate_linear_map(map, 0, tolerance);
  const AndersonRun mixed = iterate_linear_map(map, n + 1, tolerance);
  EXPECT_LE(mixed.images, n + 2);
  EXPECT_LT(mixed.images, plain.images);
  // The stop's bound: ‖G(x) − x*‖ ≤ ρ/(1 − ρ) ‖G(x) − x‖ < ρ/(1 − ρ) tol ‖G(x)‖.
  const VectorX exact = map.fixed_point();
  EXPECT_LE((mixed.last_image - exact).norm(),
            rho / (1 - rho) * tolerance * mixed.last_image.norm());
}

/// A depth below the dimension (m = 3, n = 30, eigenvalues spread over [0, 0.95]) is no
/// longer finite termination, but still needs fewer images than the plain iteration
/// (≈ log(tol)/log(0.95)), and its result obeys the same stop bound.
TEST(AndersonAcceleration, ShallowHistoryStillBeatsThePlainIteration) {
  std::vector<Real> eigenvalues;
  const int n = 30;
  for (int i = 0; i < n; ++i) eigenvalues.push_back(0.95 * i / (n - 1));
  const AndersonLinearMap map(eigenvalues);
  const Real rho = 0.95, tolerance = 1e-6;
  const AndersonRun plain = iterate_linear_map(map, 0, tolerance);
  const AndersonRun mixed = iterate_linear_map(map, 3, tolerance);
  EXPECT_LT(2 * mixed.images, plain.images) << mixed.images << " against " << plain.images;
  const VectorX exact = map.fixed_point();
  EXPECT_LE((mixed.last_image - exact).norm(),
            rho / (1 - rho) * tolerance * mixed.last_image.norm());
}

/// One dimension: G(x) = x/2 + 1 (fixed point 2). From x = 0: image 1 (plain, no
/// difference yet); from 1: image 1.5, and the mix of the two is the secant's
/// extrapolation, exactly 2.
TEST(AndersonAcceleration, OneColumnIsTheSecantExtrapolation) {
  AndersonAcceleration anderson(3);
  const VectorX first = anderson.next(VectorX::Constant(1, 0.0), VectorX::Constant(1, 1.0));
  EXPECT_EQ(anderson.last_columns(), 0);
  EXPECT_EQ(first[0], 1.0);
  const VectorX second = anderson.next(first, VectorX::Constant(1, 1.5));
  EXPECT_EQ(anderson.last_columns(), 1);
  EXPECT_NEAR(second[0], 2.0, 4 * std::numeric_limits<Real>::epsilon());
}

/// A mix whose image leaves a larger change than the step before it is dropped: the
/// next iterate is the plain image and the history restarts.
TEST(AndersonAcceleration, AMixThatIncreasesTheChangeRestarts) {
  AndersonAcceleration anderson(3);
  const VectorX first = anderson.next(VectorX::Constant(1, 0.0), VectorX::Constant(1, 1.0));
  const VectorX second = anderson.next(first, VectorX::Constant(1, 1.5)); // the mix: 2
  // The map changed under the history: from 2 the image is 5, a change 3 > 0.5.
  const VectorX third = anderson.next(second, VectorX::Constant(1, 5.0));
  EXPECT_EQ(anderson.restarts(), 1);
  EXPECT_EQ(anderson.last_columns(), 0);
  EXPECT_EQ(third[0], 5.0);
}

/// Parallel difference columns make the least-squares problem singular: restart.
TEST(AndersonAcceleration, DependentColumnsRestart) {
  AndersonAcceleration anderson(3);
  VectorX x = VectorX::Zero(2);
  x = anderson.next(x, VectorX::Unit(2, 0));           // f = (1, 0)
  x = anderson.next(x, x + 0.5 * VectorX::Unit(2, 0)); // f = (0.5, 0): mixed
  ASSERT_EQ(anderson.last_columns(), 1);
  const VectorX image = x + 0.25 * VectorX::Unit(2, 0); // f = (0.25, 0)
  const VectorX next = anderson.next(x, image);
  EXPECT_EQ(anderson.restarts(), 1);
  EXPECT_EQ(anderson.last_columns(), 0);
  EXPECT_EQ(next, image);
}

/// A step that may not be mixed (a loose one) returns its image and still enters the
/// history; forget() empties it. G(x) = diag(1/2, 1/4) x + (1, 1), fixed point (2, 4/3):
/// two columns on a linear map of dimension two give it exactly.
TEST(AndersonAcceleration, UnmixedStepsFeedTheHistoryAndForgetEmptiesIt) {
  const auto map = [](const VectorX& x) { return VectorX{{0.5 * x[0] + 1.0, 0.25 * x[1] + 1.0}}; };
  AndersonAcceleration anderson(3);
  VectorX x = anderson.next(VectorX::Zero(2), map(VectorX::Zero(2)));
  const VectorX image = map(x);
  x = anderson.next(x, image, /*may_mix=*/false);
  EXPECT_EQ(anderson.last_columns(), 0);
  EXPECT_EQ(x, image);
  x = anderson.next(x, map(x));
  EXPECT_EQ(anderson.last_columns(), 2); // the unmixed pair's column is one of them
  // Two columns, ‖x‖ < 2.5: e ≤ 2 columns · cond ε · ‖x‖ < 5 cond ε = 2.5 anderson_roundoff_change.
  EXPECT_NEAR(x[0], 2.0, 2.5 * anderson_roundoff_change);
  EXPECT_NEAR(x[1], 4.0 / 3.0, 2.5 * anderson_roundoff_change);
  anderson.forget();
  const VectorX after = anderson.next(x, map(x));
  EXPECT_EQ(anderson.last_columns(), 0);
  EXPECT_EQ(after, map(x));
}

} // namespace
} // namespace formflow::solvers
