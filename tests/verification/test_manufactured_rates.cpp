// SPDX-License-Identifier: MIT
// Theorem 4.1 for smooth solutions: ‖u − u_h‖_V = O(h^l), ‖u − u_h‖_L2 = O(h^(l+1)) for Q_l,
// on uniform and distorted (non-affine) meshes, constant viscosity and the law (5.4).
#include "support/approx.hpp"
#include "verification/verification_support.hpp"

#include <gtest/gtest.h>

#include <tuple>

namespace formflow {
namespace {

using Parameters = std::tuple<fem::ElementKind, mesh::Distortion, bool>;

class ManufacturedRates : public ::testing::TestWithParam<Parameters> {};

TEST_P(ManufacturedRates, ObservedOrdersMatchTheoremOnFinestPair) {
  const auto [element, distortion, nonlinear] = GetParam();
  const int order = fem::element_order(element);
  // Three rungs with ratio 2, small enough to run in about a second and fine
  // enough to be in the asymptotic range (docs/verification.md shows longer ladders).
  const std::vector<Real> sizes = order == 1 ? std::vector<Real>{1.0 / 8, 1.0 / 16, 1.0 / 32}
                                             : std::vector<Real>{1.0 / 4, 1.0 / 8, 1.0 / 16};
  const post::StudyTable table = testing::mesh_ladder(sizes, [&](Real size) {
    return testing::manufactured_case(element, size, distortion, nonlinear);
  });
  ASSERT_NO_FATAL_FAILURE(testing::expect_converged_errors_fall(table));
  const post::StudyRung& finest = table.rungs.back();
  ASSERT_TRUE(finest.order_v && finest.order_l2);
  // The criterion: within 0.15 of the theoretical order on the finest pair.
  EXPECT_NEAR(*finest.order_v, order, 0.15);
  // One combination is still pre-asymptotic in L2 at h = 1/32 (observed 1.63,
  // reaching 1.89 only at h = 1/128; docs/verification.md): its L2 order is
  // asserted on that longer ladder in tests/long/test_manufactured_long.cpp.
  const bool l2_needs_longer_ladder =
      element == fem::ElementKind::Q1 && distortion == mesh::Distortion::Smooth && nonlinear;
  if (!l2_needs_longer_ladder) {
    EXPECT_NEAR(*finest.order_l2, order + 1, 0.15);
  }
}

std::string name_of(const ::testing::TestParamInfo<Parameters>& info) {
  const auto [element, distortion, nonlinear] = info.param;
  const char* mesh = distortion == mesh::Distortion::None     ? "Uniform"
                     : distortion == mesh::Distortion::Smooth ? "Smooth"
                                                              : "Random";
  return std::string(fem::element_name(element)) + mesh + (nonlinear ? "PowerLaw" : "Constant");
}

INSTANTIATE_TEST_SUITE_P(
    Theorem41, ManufacturedRates,
    ::testing::Combine(::testing::Values(fem::ElementKind::Q1, fem::ElementKind::Q2),
                       ::testing::Values(mesh::Distortion::None, mesh::Distortion::Smooth,
                                         mesh::Distortion::Random),
                       ::testing::Bool()),
    name_of);

/// P2+–P1disc on triangles (each square of the box cut along its diagonal, distorted
/// with it): Theorem 4.1's orders of a quadratic element, 2 in V and 3 in L2. The
/// triangles approach them more slowly than Q2 (V: 1.70, 1.81, 1.92 from h = 1/4 to
/// 1/32 on the uniform mesh, not d's doing: the same at d = 1e-6), so the ladder starts
/// at h = 1/8. On the smoothly distorted box the constant-viscosity run still shows V
/// order 1.82 at h = 1/32 (docs/simplices.md lists it as open), so the distorted
/// meshes are not asserted here.
class ManufacturedTriangleRates
    : public ::testing::TestWithParam<std::tuple<mesh::Distortion, bool>> {};

TEST_P(ManufacturedTriangleRates, ObservedOrdersAreQuadraticOnFinestPair) {
  const auto [distortion, nonlinear] = GetParam();
  const post::StudyTable table =
      testing::mesh_ladder({1.0 / 8, 1.0 / 16, 1.0 / 32}, [&](Real size) {
        return testing::simplex_manufactured_case(size, 2, distortion, nonlinear);
      });
  ASSERT_TRUE(table.all_converged());
  const post::StudyRung& finest = table.rungs.back();
  ASSERT_TRUE(finest.order_v && finest.order_l2);
  EXPECT_NEAR(*finest.order_v, 2.0, 0.15);
  EXPECT_NEAR(*finest.order_l2, 3.0, 0.15);
}

INSTANTIATE_TEST_SUITE_P(
    Theorem41, ManufacturedTriangleRates,
    ::testing::Combine(::testing::Values(mesh::Distortion::None), ::testing::Bool()),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) == mesh::Distortion::None ? "Uniform" : "Smooth") +
             (std::get<1>(info.param) ? "PowerLaw" : "Constant");
    });

} // namespace
} // namespace formflow
