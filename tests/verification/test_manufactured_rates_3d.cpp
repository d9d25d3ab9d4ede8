// SPDX-License-Identifier: MIT
// Theorem 4.1 in 3D: ‖u − u_h‖_V = O(h^l), ‖u − u_h‖_L2 = O(h^(l+1)) for Q_l hexahedra,
// the vector-potential field on the unit cube (physics/manufactured_3d.hpp), constant
// viscosity. The default suite holds the ladders that are asymptotic within about 15 k
// dofs (Q1 on smoothly distorted hexahedra, Q2 on uniform ones); Q2 on distorted
// hexahedra needs h = 1/16 (108 k dofs): tests/long/test_manufactured_3d_long.cpp.
#include "verification/verification_support.hpp"

#include <gtest/gtest.h>

#include <tuple>

namespace formflow {
namespace {

using SolidRateParameters = std::tuple<fem::ElementKind, mesh::Distortion>;

class ManufacturedRates3d : public ::testing::TestWithParam<SolidRateParameters> {};

TEST_P(ManufacturedRates3d, ObservedOrdersMatchTheoremOnFinestPair) {
  const auto [element, distortion] = GetParam();
  const int order = fem::element_order(element);
  // Three rungs with ratio 2, the finest at 14 739 dofs for both elements.
  const std::vector<Real> sizes = order == 1 ? std::vector<Real>{1.0 / 4, 1.0 / 8, 1.0 / 16}
                                             : std::vector<Real>{1.0 / 2, 1.0 / 4, 1.0 / 8};
  const post::StudyTable table = testing::mesh_ladder(sizes, [&](Real size) {
    io::Case case_ = testing::manufactured_case(element, size, distortion, false);
    case_.mesh.dimension = 3;
    return case_;
  });
  ASSERT_NO_FATAL_FAILURE(testing::expect_converged_errors_fall(table));
  const post::StudyRung& finest = table.rungs.back();
  ASSERT_TRUE(finest.order_v && finest.order_l2);
  // The criterion: within 0.15 of the theoretical order on the finest pair.
  EXPECT_NEAR(*finest.order_v, order, 0.15);
  EXPECT_NEAR(*finest.order_l2, order + 1, 0.15);
}

std::string solid_rate_case_name(const ::testing::TestParamInfo<SolidRateParameters>& info) {
  const auto [element, distortion] = info.param;
  const char* mesh = distortion == mesh::Distortion::None     ? "Uniform"
                     : distortion == mesh::Distortion::Smooth ? "Smooth"
                                                              : "Random";
  return std::string(fem::element_name(element)) + mesh;
}

INSTANTIATE_TEST_SUITE_P(
    Theorem41, ManufacturedRates3d,
    ::testing::Values(SolidRateParameters{fem::ElementKind::Q1, mesh::Distortion::Smooth},
                      SolidRateParameters{fem::ElementKind::Q2, mesh::Distortion::None}),
    solid_rate_case_name);

// P2+ tetrahedra (P2 with face and cell bubbles, P1disc pressure condensed with d > 0), the
// unit cube's cells cut into six tetrahedra each: ‖u − u_h‖_V = O(h²), ‖u − u_h‖_L2 = O(h³),
// within 0.15 on the finest pair (h = 1/4, 1/8, 43 539 dofs).
TEST(ManufacturedTetrahedronRates, ObservedOrdersMatchTheoremOnFinestPair) {
  const post::StudyTable table = testing::mesh_ladder({1.0 / 2, 1.0 / 4, 1.0 / 8}, [&](Real size) {
    return testing::simplex_manufactured_case(size, 3, mesh::Distortion::None, false);
  });
  ASSERT_NO_FATAL_FAILURE(testing::expect_converged_errors_fall(table));
  const post::StudyRung& finest = table.rungs.back();
  ASSERT_TRUE(finest.order_v && finest.order_l2);
  EXPECT_NEAR(*finest.order_v, 2.0, 0.15);
  EXPECT_NEAR(*finest.order_l2, 3.0, 0.15);
}

} // namespace
} // namespace formflow
