// SPDX-License-Identifier: MIT
// A distributed run's assembly without MPI (issue 20, docs/petsc.md): the ranks'
// shares of the secant system (each rank's own cells, volume and Γ3 friction terms)
// add up to the serial system, each share holds only its cells' entries, and the
// slab partition (or a graph partitioner's, here one that interleaves the cells) gives
// every cell to exactly one rank; so do Newton's tangent, internal force and coupling
// product.
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/cell_partition.hpp"
#include "formflow/mesh/channel_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace formflow::assembly {
namespace {

mesh::Mesh<2> channel() {
  const mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0}; // L_c, H_in, H_out, L_e
  return mesh::make_channel_mesh(geometry, 0.5, 2);
}

ProblemSettings settings(Distribution distribution = {}) {
  ProblemSettings settings;
  settings.penalty.d = 1e-3;
  settings.friction.mu = 0.1; // the Γ3 friction terms of the own cells' faces
  settings.distribution = std::move(distribution);
  return settings;
}

/// A non-uniform velocity, so that viscosities and slips vary from cell to cell.
VectorX lagged_velocity(const mesh::Mesh<2>& mesh) {
  VectorX w(mesh.n_nodes() * 2);
  for (Index node = 0; node < mesh.n_nodes(); ++node) {
    const Real x = mesh.nodes(0, node), y = mesh.nodes(1, node);
    w[fem::dof_of<2>(node, 0)] = 1.0 + 0.3 * std::sin(x) * y;
    w[fem::dof_of<2>(node, 1)] = 0.2 * x * y - 0.1 * y * y;
  }
  return w;
}

TEST(SlabPartition, EveryCellInOnePartEqualSizesOrderedAlongX) {
  const mesh::Mesh<2> mesh = channel();
  for (int parts : {1, 2, 3, 7}) {
    const std::vector<int> part = mesh::slab_partition(mesh, parts);
    ASSERT_EQ(static_cast<Index>(part.size()), mesh.n_cells());
    std::vector<Index> count(parts, 0);
    std::vector<Real> lowest(parts, std::numeric_limits<Real>::infinity());
    std::vector<Real> highest(parts, -std::numeric_limits<Real>::infinity());
    for (Index cell = 0; cell < mesh.n_cells(); ++cell) {
      ASSERT_GE(part[cell], 0);
      ASSERT_LT(part[cell], parts);
      ++count[part[cell]];
      Real x = 0;
      for (Index a = 0; a < mesh.cells.rows(); ++a) x += mesh.nodes(0, mesh.cells(a, cell));
      x /= static_cast<Real>(mesh.cells.rows());
      lowest[part[cell]] = std::min(lowest[part[cell]], x);
      highest[part[cell]] = std::max(highest[part[cell]], x);
    }
    const auto [smallest, largest] = std::minmax_element(count.begin(), count.end());
    EXPECT_LE(*largest - *smallest, 1) << parts << " parts";
    for (int r = 0; r + 1 < parts; ++r) EXPECT_LE(highest[r], lowest[r + 1]) << "slab " << r;
  }
}

TEST(DistributedShares, AddUpToTheSerialSystemAndHoldOnlyTheirCells) {
  const mesh::Mesh<2> mesh = channel();
  const FormingProblem<2> serial(mesh, settings());
  const VectorX w = lagged_velocity(mesh);
  LinearSystem whole = serial.plan().make_system();
  serial.assemble(&w, whole);
  ASSERT_GT(serial.n_contact_points(), 0);

  // Cells interleaved among the ranks (cell c on rank c mod N), through the graph
  // partitioner's seam: parts that are not contiguous in x, as PT-Scotch's need not be.
  const mesh::GraphPartitioner interleaved = [](const mesh::CellGraph& graph, int parts) {
    mesh::CellPartition split{std::vector<int>(static_cast<std::size_t>(graph.n_cells())),
                              "interleaved"};
    for (Index cell = 0; cell < graph.n_cells(); ++cell)
      split.part[cell] = static_cast<int>(cell % parts);
    return split;
  };
  for (const auto& [ranks, partitioner] : {std::pair<int, mesh::GraphPartitioner>{2, nullptr},
                                           {3, nullptr},
                                           {2, interleaved},
                                           {3, interleaved}}) {
    SCOPED_TRACE(partitioner ? "interleaved cells" : "slabs");
    MatrixX sum = MatrixX::Zero(whole.matrix.rows(), whole.matrix.cols());
    MatrixX magnitude = sum; // Σ_r |K_r|, for the round-off bounds below
    VectorX rhs = VectorX::Zero(whole.rhs.size()), rhs_magnitude = rhs;
    MatrixX reactions = MatrixX::Zero(whole.reaction_rows.rows(), whole.reaction_rows.cols());
    MatrixX reaction_magnitude = reactions;
    Real force = 0, force_magnitude = 0; // Σ_r f_r and Σ of |its terms|
    Index force_terms = 0;
    std::vector<int> owner(mesh.n_cells(), -1);
    for (int rank = 0; rank < ranks; ++rank) {
      // One process plays every rank: the sum over ranks is the caller's here (a no-op).
      Distribution distribution{rank, ranks, [](std::span<Real>) {}, partitioner};
      const FormingProblem<2> share_problem(mesh, settings(distribution));
      for (const Index cell : share_problem.discretisation().assembled_cells()) {
        EXPECT_EQ(owner[cell], -1) << "cell " << cell << " assembled twice";
        owner[cell] = rank;
        if (partitioner) {
          EXPECT_EQ(cell % ranks, rank) << "not the partitioner's split";
        }
      }
      EXPECT_EQ(share_problem.discretisation().partition_method(),
                partitioner ? "interleaved" : "slabs");
      LinearSystem share = share_problem.plan().make_system();
      share_problem.assemble(&w, share);
      // The share's pattern is its cells' entries only: less than the whole.
      EXPECT_LT(share.matrix.nonZeros(), whole.matrix.nonZeros());
      sum += MatrixX(share.matrix);
      magnitude += MatrixX(share.matrix).cwiseAbs();
      rhs += share.rhs;
      rhs_magnitude += share.rhs.cwiseAbs();
      reactions += MatrixX(share.reaction_rows);
      reaction_magnitude += MatrixX(share.reaction_rows).cwiseAbs();
      force += share_problem.driven_force(share, w);
      for (const Index dof : serial.constraints().driven_dofs) {
        const Index row = serial.plan().prescribed_index(dof);
        const MatrixX dense_row = MatrixX(share.reaction_rows).row(row);
        force_magnitude +=
            (dense_row.cwiseAbs() * w.cwiseAbs()).sum() + std::abs(share.prescribed_loads[row]);
        force_terms += share.reaction_rows.cols() + 1;
      }
    }
    EXPECT_EQ(std::count(owner.begin(), owner.end(), -1), 0) << "a cell no rank assembled";
    // Each entry is a sum over the (at most 4) cells of a 2D quadrilateral mesh that
    // share a node, each cell's part itself a sum of quadrature and face terms. The
    // ranks add the same cell parts in another order, which moves a sum of m ≤ 4 terms
    // by at most (m − 1) ε Σ|terms| ≤ 3 ε Σ|terms|, and Σ|terms| ≤ Σ_r |K_r| only up
    // to the cancellation inside a rank's share; twice that, 6 ε Σ_r |K_r|, is the bound
    // (the same for the rhs and the reaction rows).
    constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
    constexpr Real tiny = std::numeric_limits<Real>::min();
    const auto within = [&](const MatrixX& a, const MatrixX& b, const MatrixX& size) {
      return ((a - b).cwiseAbs().array() <= 6 * epsilon * size.array() + tiny).all();
    };
    EXPECT_TRUE(within(sum, MatrixX(whole.matrix), magnitude)) << ranks << " ranks";
    EXPECT_TRUE(within(rhs, whole.rhs, rhs_magnitude)) << ranks << " ranks";
    EXPECT_TRUE(within(reactions, MatrixX(whole.reaction_rows), reaction_magnitude))
        << ranks << " ranks";
    // The process force is a sum of M terms (reaction entries times u, loads) taken in
    // two orders: at most 2 M ε Σ|terms| apart (the rows' own 6 ε is below that).
    const Real serial_force = serial.driven_force(whole, w);
    EXPECT_NEAR(force, serial_force,
                2 * static_cast<Real>(force_terms) * epsilon * force_magnitude);
  }
}

TEST(DistributedShares, PowersOfTheRanksCellsAddUpToTheSerialPowers) {
  // Each rank's power pass covers its own cells and their Γ3 faces (the sum over ranks
  // is a no-op here, so each returns its part): every term's parts add up to the
  // serial term, and no cell or face is counted twice (a doubled cell would add its
  // whole share, far above round-off).
  const mesh::Mesh<2> mesh = channel();
  const VectorX w = lagged_velocity(mesh);
  const FormingProblem<2> serial(mesh, settings());
  const PowerTerms whole = serial.powers(w, serial.contact_state(w));
  ASSERT_GT(whole.friction, 0) << "no friction power to share";
  const auto terms = [](const PowerTerms& p) {
    return std::array<Real, 5>{p.plastic_dissipation, p.viscous_form, p.volumetric_penalty,
                               p.contact_penalty, p.friction};
  };
  for (int ranks : {2, 3}) {
    std::array<Real, 5> sum{}, magnitude{};
    for (int rank = 0; rank < ranks; ++rank) {
      const FormingProblem<2> share(mesh, settings({rank, ranks, [](std::span<Real>) {}}));
      const std::array<Real, 5> part = terms(share.powers(w, share.contact_state(w)));
      for (std::size_t t = 0; t < part.size(); ++t) {
        sum[t] += part[t];
        magnitude[t] += std::abs(part[t]);
      }
    }
    // A term is a sum of N point terms (the full and volumetric rules' points of every
    // cell, the Γ3 points) in another grouping: at most N ε Σ|point terms| apart. With
    // the penalty every integrand is non-negative (the dissipations, ε_V²/d, u_N²/d_N,
    // τ |u_T|²/√(|u_T|² + d_T²)), so Σ|point terms| = Σ|parts|; the factor 2 covers
    // the additions of the parts themselves.
    const auto& discretisation = serial.discretisation();
    const Real n_terms = static_cast<Real>(discretisation.full_rule().size() +
                                           discretisation.volumetric_rule().size()) *
                             static_cast<Real>(mesh.n_cells()) +
                         static_cast<Real>(serial.n_contact_points());
    const std::array<Real, 5> expected = terms(whole);
    for (std::size_t t = 0; t < sum.size(); ++t)
      EXPECT_NEAR(sum[t], expected[t],
                  2 * n_terms * std::numeric_limits<Real>::epsilon() * magnitude[t] +
                      std::numeric_limits<Real>::min())
          << "term " << t << ", " << ranks << " ranks";
  }
}

/// What one rank's Newton assembly at `w` gives: its tangent share, its internal force
/// (its own cells' forces: the sum over ranks is a no-op here) and its share of N x.
struct NewtonShare {
  MatrixX tangent;
  VectorX force, product;
};

NewtonShare newton_share(const mesh::Mesh<2>& mesh, const Distribution& distribution,
                         const VectorX& w, const VectorX& x) {
  const FormingProblem<2> problem(mesh, settings(distribution));
  LinearSystem tangent = problem.plan().make_system();
  UnsymmetricTangent<2> coupling;
  NewtonShare share;
  problem.assemble_newton(w, problem.friction_thresholds(w), NewtonDuals<2>{}, share.force,
                          &tangent, &coupling);
  share.tangent = MatrixX(tangent.matrix);
  share.product = VectorX::Zero(x.size());
  problem.apply_coupling(coupling, x, share.product);
  return share;
}

TEST(DistributedShares, NewtonTangentForceAndCouplingAddUpToTheSerialOnes) {
  const mesh::Mesh<2> mesh = channel();
  const VectorX w = lagged_velocity(mesh);
  const FormingProblem<2> serial_problem(mesh, settings());
  VectorX x(serial_problem.plan().n_free()); // a free vector to multiply N by
  for (Index i = 0; i < x.size(); ++i) x[i] = std::cos(0.7 * static_cast<Real>(i));
  const NewtonShare serial = newton_share(mesh, {}, w, x);
  ASSERT_GT(serial.product.cwiseAbs().maxCoeff(), 0) << "no coupling to share";
  // The cells' own parts: one cell per rank (the slab partition of n_cells parts).
  const int n_cells = static_cast<int>(mesh.n_cells());
  MatrixX tangent_parts = MatrixX::Zero(serial.tangent.rows(), serial.tangent.cols());
  VectorX force_parts = VectorX::Zero(serial.force.size());
  VectorX product_parts = VectorX::Zero(serial.product.size());
  for (int cell = 0; cell < n_cells; ++cell) {
    const NewtonShare part = newton_share(mesh, {cell, n_cells, [](std::span<Real>) {}}, w, x);
    tangent_parts += part.tangent.cwiseAbs();
    force_parts += part.force.cwiseAbs();
    product_parts += part.product.cwiseAbs();
  }
  // A cell's part is computed alike whether its rank holds it alone, with others or all
  // cells; an entry of T or f is then a sum of at most m = 4 cells' parts (2D
  // quadrilaterals at a node) taken in two orders, each within (m − 1) ε Σ|parts| of the
  // exact sum: 6 ε Σ|parts| apart. N x adds point by point: m ≤ 36 point terms (4 cells ×
  // 9 Q2 points; a Γ3 node has 2 cells and 2 × 3 face points), 70 ε Σ|terms| apart, with
  // Σ|terms| taken as the largest Σ|cell parts| (up to the cancellation inside a cell).
  constexpr Real epsilon = std::numeric_limits<Real>::epsilon();
  constexpr Real tiny = std::numeric_limits<Real>::min();
  for (int ranks : {2, 3}) {
    MatrixX tangent = MatrixX::Zero(serial.tangent.rows(), serial.tangent.cols());
    VectorX force = VectorX::Zero(serial.force.size());
    VectorX product = VectorX::Zero(serial.product.size());
    for (int rank = 0; rank < ranks; ++rank) {
      const NewtonShare share = newton_share(mesh, {rank, ranks, [](std::span<Real>) {}}, w, x);
      tangent += share.tangent;
      force += share.force;
      product += share.product;
    }
    EXPECT_TRUE(((tangent - serial.tangent).cwiseAbs().array() <=
                 6 * epsilon * tangent_parts.array() + tiny)
                    .all())
        << ranks << " ranks";
    EXPECT_TRUE(
        ((force - serial.force).cwiseAbs().array() <= 6 * epsilon * force_parts.array() + tiny)
            .all())
        << ranks << " ranks";
    const Real max_product = product_parts.cwiseAbs().maxCoeff();
    EXPECT_LE((product - serial.product).cwiseAbs().maxCoeff(), 70 * epsilon * max_product)
        << ranks << " ranks";
  }
}

} // namespace
} // namespace formflow::assembly
