// SPDX-License-Identifier: MIT
// Remark 5.1 at the level of the assembled matrices: reduced integration of the
// penalty term is a mixed method with a discontinuous pressure.
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/channel_mesh.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace formflow::assembly {
namespace {

mesh::Mesh<2> small_channel(int order) {
  const mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0}; // L_c, H_in, H_out, L_e
  return mesh::make_channel_mesh(geometry, 0.5, order);
}

ProblemSettings settings(int volumetric_points) {
  ProblemSettings settings;
  settings.process.ram = physics::RamCondition::Sticking;
  settings.penalty.d = 1e-3;
  settings.volumetric_points = volumetric_points;
  return settings;
}

/// A smooth, non-uniform velocity so that the secant viscosity varies in every cell.
VectorX mixed_lagged_velocity(const mesh::Mesh<2>& mesh) {
  VectorX w(mesh.n_nodes() * 2);
  for (Index node = 0; node < mesh.n_nodes(); ++node) {
    const Real x = mesh.nodes(0, node), y = mesh.nodes(1, node);
    w[fem::dof_of<2>(node, 0)] = 1.0 + 0.3 * std::sin(x) * y;
    w[fem::dof_of<2>(node, 1)] = 0.2 * x * y - 0.1 * y * y;
  }
  return w;
}

/// K of the penalty problem with `points` volumetric Gauss points, and K of the
/// mixed problem with pressure `space` (condensed), both at the same lagged w.
std::pair<MatrixX, MatrixX> penalty_and_mixed(int order, int points, fem::PressureSpace space) {
  const mesh::Mesh<2> mesh = small_channel(order);
  const ProblemSettings penalty_settings = settings(points);
  FormingProblem<2> penalty(mesh, penalty_settings), mixed(mesh, penalty_settings);
  Formulation formulation;
  formulation.type = FormulationType::Mixed;
  formulation.pressure = space;
  ConstraintMultipliers<2> multipliers(mesh, penalty_settings.penalty, formulation,
                                       mixed.full_rule(), mixed.n_contact_points());
  mixed.attach_multipliers(&multipliers);
  const VectorX w = mixed_lagged_velocity(mesh);
  LinearSystem a = penalty.plan().make_system(), b = mixed.plan().make_system();
  penalty.assemble(&w, a);
  mixed.assemble(&w, b);
  return {MatrixX(a.matrix), MatrixX(b.matrix)}; // lower triangles
}

Real relative_difference(const MatrixX& a, const MatrixX& b) {
  return (a - b).norm() / a.norm();
}

// The volumetric block is (1/d)·1e3 times larger than the viscous one, so round-off
// is relative to ‖K‖: 1e-13 leaves room for the few hundred summed terms per entry.
constexpr Real round_off = 1e-13;

TEST(MixedEquivalence, Q1PenaltyWithOnePointRuleIsQ1P0) {
  const auto [penalty, mixed] = penalty_and_mixed(1, 1, fem::PressureSpace::P0);
  EXPECT_LT(relative_difference(penalty, mixed), round_off);
  // (the right-hand sides are K_fc u_c of the same matrices, so equal too)
}

TEST(MixedEquivalence, Q1CompleteRuleIsNotQ1P0) {
  // The complete 2×2 rule is the locking Q1–Q1disc pairing, clearly different.
  const auto [penalty, mixed] = penalty_and_mixed(1, 2, fem::PressureSpace::P0);
  EXPECT_GT(relative_difference(penalty, mixed), 1e3 * round_off); // not round-off
}

TEST(MixedEquivalence, Q2PenaltyWithTwoByTwoRuleIsQ2Q1disc) {
  // 2×2 Gauss points carry exactly a bilinear (Q1) polynomial per cell: the
  // reduced rule is the mixed method with discontinuous bilinear pressure.
  const auto [penalty, mixed] = penalty_and_mixed(2, 2, fem::PressureSpace::Q1disc);
  EXPECT_LT(relative_difference(penalty, mixed), round_off);
}

TEST(MixedEquivalence, Q2TwoByTwoDiffersFromQ2P1discOnlyInTheBilinearPressureMode) {
  // Q1disc = P1disc ⊕ span{ξη}: the difference of the two condensed matrices
  // is positive semidefinite with rank at most one per cell (the ξη mode).
  const auto [penalty, mixed] = penalty_and_mixed(2, 2, fem::PressureSpace::P1disc);
  const MatrixX difference = MatrixX(penalty.selfadjointView<Eigen::Lower>()) -
                             MatrixX(mixed.selfadjointView<Eigen::Lower>());
  const Eigen::SelfAdjointEigenSolver<MatrixX> eigen(difference, Eigen::EigenvaluesOnly);
  const VectorX& lambda = eigen.eigenvalues();
  const Real scale = lambda.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 1e-3 * MatrixX(penalty).norm()); // not equal: P1disc is not Q1disc
  EXPECT_GT(lambda.minCoeff(), -1e-10 * scale);     // semidefinite
  const Index rank = (lambda.array() > 1e-10 * scale).count();
  const Index n_cells = small_channel(2).n_cells();
  EXPECT_LE(rank, n_cells);
  EXPECT_GE(rank, n_cells / 2);
}

TEST(MixedEquivalence, Q2PenaltyWithOnePointRuleIsNotQ2P0) {
  // Remark 5.1: Q2 with 1×1 is not {Q2, P0}: ∫div u over the cell ≠ |cell|·div u(centre).
  const auto [penalty, mixed] = penalty_and_mixed(2, 1, fem::PressureSpace::P0);
  EXPECT_GT(relative_difference(penalty, mixed), 1e3 * round_off); // not round-off
}

} // namespace
} // namespace formflow::assembly
