// SPDX-License-Identifier: MIT
// The discontinuous pressure kept as a saddle point in a distributed run, without MPI
// (issue 20, docs/petsc.md "Distributed runs"): the ranks' shares of [A Bᵀ; B −dM], of its
// right-hand side and of the Schur preconditioner add up to the serial ones; each share
// has the diagonal of exactly its own cells' pressure rows (PETSc's numbering gives a row
// to the lowest rank that has its diagonal, so each pressure dof goes to its cell's rank);
// and what every rank must agree on (the null-mode pin, the zero-mean shift) is the serial
// decision on every share.
#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/assembly/saddle_point_system.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/channel_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace formflow::assembly {
namespace {

mesh::Mesh<2> saddle_share_channel() {
  const mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0}; // L_c, H_in, H_out, L_e
  return mesh::make_channel_mesh(geometry, 0.5, 2);
}

ProblemSettings saddle_share_settings(Real d, Distribution distribution = {}) {
  ProblemSettings settings;
  settings.penalty.d = d;
  settings.friction.mu = 0.1; // the Γ3 friction terms of the own cells' faces
  settings.distribution = std::move(distribution);
  return settings;
}

/// A non-uniform velocity, so that viscosities (and the Schur blocks) vary by cell.
VectorX saddle_share_velocity(const mesh::Mesh<2>& mesh) {
  VectorX w(mesh.n_nodes() * 2);
  for (Index node = 0; node < mesh.n_nodes(); ++node) {
    const Real x = mesh.nodes(0, node), y = mesh.nodes(1, node);
    w[fem::dof_of<2>(node, 0)] = 1.0 + 0.3 * std::sin(x) * y;
    w[fem::dof_of<2>(node, 1)] = 0.2 * x * y - 0.1 * y * y;
  }
  return w;
}

/// One rank's (or the serial) saddle point at the lagged velocity w and pressure p.
struct SaddleShare {
  MatrixX matrix, schur;
  VectorX rhs, level; ///< level: fix_pressure_level of a test pressure
  bool pinned = false;
  std::vector<Index> cells; ///< the cells this rank assembles
  /// Whether the share's pattern holds the diagonal of pressure dof q (structurally).
  std::vector<bool> pressure_diagonal;
};

SaddleShare saddle_share(const mesh::Mesh<2>& mesh, Real d, const Distribution& distribution,
                         const VectorX& w) {
  FormingProblem<2> problem(mesh, saddle_share_settings(d, distribution));
  Formulation formulation;
  formulation.type = FormulationType::Mixed;
  formulation.pressure = fem::PressureSpace::P1disc;
  formulation.discontinuous = DiscontinuousPressure::SaddlePoint;
  ConstraintMultipliers<2> multipliers(mesh, saddle_share_settings(d).penalty, formulation,
                                       problem.full_rule(), problem.n_contact_points());
  problem.attach_multipliers(&multipliers);
  EXPECT_TRUE(multipliers.has_global_pressure());
  LinearSystem velocity = problem.plan().make_system();
  problem.assemble(&w, velocity);
  SaddlePointSystem<2> saddle(problem, multipliers);
  saddle.fill_matrix(velocity);
  VectorX pressure(saddle.n_pressure());
  for (Index q = 0; q < pressure.size(); ++q) pressure[q] = std::sin(1.3 * static_cast<Real>(q));
  SaddleShare share;
  share.matrix = MatrixX(saddle.matrix());
  share.schur = MatrixX(saddle.schur_preconditioner());
  share.rhs = saddle.rhs(velocity, pressure);
  share.level = pressure;
  saddle.fix_pressure_level(share.level);
  share.pinned = saddle.has_pinned_pressure();
  share.cells = problem.discretisation().assembled_cells();
  const SparseMatrix& pattern = saddle.matrix();
  for (Index q = 0; q < saddle.n_pressure(); ++q) {
    const Index column = saddle.n_velocity() + q;
    const Index* begin = pattern.innerIndexPtr() + pattern.outerIndexPtr()[column];
    const Index* end = pattern.innerIndexPtr() + pattern.outerIndexPtr()[column + 1];
    share.pressure_diagonal.push_back(std::binary_search(begin, end, column));
  }
  return share;
}

TEST(DistributedSaddlePointShares, AddUpToTheSerialSaddlePointEachPressureRowOnItsCellsRank) {
  const mesh::Mesh<2> mesh = saddle_share_channel();
  const VectorX w = saddle_share_velocity(mesh);
  constexpr Index n_p = 3; // P1disc in 2D: pressure dofs cell·3 + k
  for (const Real d : {1e-3, 0.0}) {
    const SaddleShare serial = saddle_share(mesh, d, {}, w);
    for (int ranks : {2, 3}) {
      MatrixX matrix = MatrixX::Zero(serial.matrix.rows(), serial.matrix.cols());
      MatrixX magnitude = matrix; // Σ_r |share_r|, for the round-off bound below
      MatrixX schur = MatrixX::Zero(serial.schur.rows(), serial.schur.cols());
      VectorX rhs = VectorX::Zero(serial.rhs.size()), rhs_magnitude = rhs;
      for (int rank = 0; rank < ranks; ++rank) {
        const SaddleShare share = saddle_share(mesh, d, {rank, ranks, [](std::span<Real>) {}}, w);
        matrix += share.matrix;
        magnitude += share.matrix.cwiseAbs();
        schur += share.schur;
        rhs += share.rhs;
        rhs_magnitude += share.rhs.cwiseAbs();
        // The global decisions are the serial ones, bit for bit (taken from every cell).
        EXPECT_EQ(share.pinned, serial.pinned);
        EXPECT_EQ(share.level, serial.level);
        // The diagonal of a pressure row: in the share of its cell's rank, in no other.
        std::vector<bool> own(serial.schur.rows(), false);
        for (const Index cell : share.cells)
          for (Index k = 0; k < n_p; ++k) own[cell * n_p + k] = true;
        EXPECT_EQ(share.pressure_diagonal, own) << "d " << d << ", rank " << rank << "/" << ranks;
      }
      // The velocity block is A's shares (tests/unit/assembly/test_distributed_shares.cpp:
      // a sum of at most 4 cells' parts in another order, within 6 ε Σ_r |A_r|); B, Bᵀ,
      // −dM, the Schur blocks and the pressure rows' loads are each one cell's, copied
      // (the Schur blocks of the own cells are the serial ones bit for bit: the same
      // viscosities at the same points).
      constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
      constexpr Real tiny = std::numeric_limits<Real>::min();
      EXPECT_TRUE(
          ((matrix - serial.matrix).cwiseAbs().array() <= 6 * epsilon * magnitude.array() + tiny)
              .all())
          << "d " << d << ", " << ranks << " ranks";
      EXPECT_TRUE(
          ((rhs - serial.rhs).cwiseAbs().array() <= 6 * epsilon * rhs_magnitude.array() + tiny)
              .all())
          << "d " << d << ", " << ranks << " ranks";
      EXPECT_EQ(schur, serial.schur) << "d " << d << ", " << ranks << " ranks";
    }
  }
}

} // namespace
} // namespace formflow::assembly
