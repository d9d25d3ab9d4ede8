// SPDX-License-Identifier: MIT
// The ownership of a distributed run's ghosted vectors, without MPI (issue 20,
// docs/petsc.md "Distributed runs"): one process plays every rank. Every dof is owned by
// exactly one rank, the lowest whose cells touch it (PETSc's rule, so the solve hands
// each rank its owned rows); the ranks' owned dot products add up to the whole one; and
// the R factor over the ranks' rows (TSQR, Anderson's least squares) is that of the
// whole matrix.
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/fem/dof_map.hpp"
#include "formflow/mesh/channel_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace formflow::assembly {
namespace {

mesh::Mesh<2> owned_dofs_channel() {
  const mesh::ChannelGeometry geometry{2.0, 2.0, 1.0, 2.0}; // L_c, H_in, H_out, L_e
  return mesh::make_channel_mesh(geometry, 0.5, 2);
}

ProblemSettings owned_dofs_settings(Distribution distribution) {
  ProblemSettings settings;
  settings.penalty.d = 1e-3;
  settings.distribution = std::move(distribution);
  return settings;
}

/// Cells interleaved among the ranks (cell c on rank c mod N): every node sits between
/// ranks, the hardest case for the lowest-rank rule.
mesh::GraphPartitioner owned_dofs_interleaved() {
  return [](const mesh::CellGraph& graph, int parts) {
    mesh::CellPartition split;
    split.method = "interleaved";
    for (Index cell = 0; cell < graph.n_cells(); ++cell)
      split.part.push_back(static_cast<int>(cell % parts));
    return split;
  };
}

TEST(OwnedDofs, EveryDofHasOneOwnerTheLowestRankWhoseCellsTouchIt) {
  const mesh::Mesh<2> mesh = owned_dofs_channel();
  for (const auto& partitioner : {mesh::GraphPartitioner{}, owned_dofs_interleaved()})
    for (int ranks : {2, 3}) {
      std::vector<int> owners(static_cast<std::size_t>(mesh.n_nodes()) * 2, 0);
      std::vector<int> lowest_toucher(owners.size(), ranks);
      std::vector<VectorX> masks;
      for (int rank = 0; rank < ranks; ++rank) {
        // The sum over the ranks is a no-op here: replicate leaves each rank's owned entries.
        const FormingProblem<2> share(
            mesh, owned_dofs_settings({rank, ranks, [](std::span<Real>) {}, partitioner}));
        const OwnedDofs& owned = share.discretisation().owned_dofs();
        ASSERT_TRUE(owned.distributed());
        VectorX mask = VectorX::Ones(share.n_dofs());
        owned.replicate(mask);
        for (Index dof = 0; dof < mask.size(); ++dof) owners[dof] += mask[dof] == 1.0 ? 1 : 0;
        for (const Index cell : share.discretisation().assembled_cells())
          for (Index a = 0; a < mesh.cells.rows(); ++a)
            for (int i = 0; i < 2; ++i) {
              const Index dof = fem::dof_of<2>(mesh.cells(a, cell), i);
              lowest_toucher[dof] = std::min(lowest_toucher[dof], rank);
            }
        // The free vectors' mask is the full one's on the free dofs.
        VectorX free_mask = VectorX::Ones(share.plan().n_free());
        owned.replicate(free_mask);
        EXPECT_EQ(free_mask, share.plan().free_values(mask)) << rank << " of " << ranks;
        masks.push_back(std::move(mask));
      }
      for (std::size_t dof = 0; dof < owners.size(); ++dof)
        ASSERT_EQ(owners[dof], 1) << "dof " << dof << ", " << ranks << " ranks";
      // Each rank's owned dofs are the ones whose lowest toucher it is.
      for (int rank = 0; rank < ranks; ++rank)
        for (Index dof = 0; dof < masks[rank].size(); ++dof)
          EXPECT_EQ(masks[rank][dof] == 1.0, lowest_toucher[dof] == rank) << "dof " << dof;
    }
}

TEST(OwnedDofs, TheRanksDotProductsAddUpToTheWholeOne) {
  const mesh::Mesh<2> mesh = owned_dofs_channel();
  const Index n = mesh.n_nodes() * 2;
  VectorX a(n), b(n);
  for (Index i = 0; i < n; ++i) {
    a[i] = std::sin(0.37 * static_cast<Real>(i)) + 0.1;
    b[i] = std::cos(0.11 * static_cast<Real>(i)) - 0.4;
  }
  const int ranks = 3;
  Real sum = 0.0;
  for (int rank = 0; rank < ranks; ++rank) {
    const FormingProblem<2> share(
        mesh, owned_dofs_settings({rank, ranks, [](std::span<Real>) {}, owned_dofs_interleaved()}));
    // Another rank's entries are NaN in a ghosted vector: the dot product never reads them.
    VectorX a_ghosted = a;
    VectorX mask = VectorX::Ones(n);
    share.discretisation().owned_dofs().replicate(mask);
    for (Index i = 0; i < n; ++i)
      if (mask[i] == 0.0) a_ghosted[i] = std::numeric_limits<Real>::quiet_NaN();
    sum += share.discretisation().owned_dofs().dot(a_ghosted, b);
  }
  // The same n products summed in another order: each partial sum errs by at most
  // n ε Σ|aᵢ bᵢ| (the recursive-summation bound).
  const Real bound = static_cast<Real>(n) * std::numeric_limits<Real>::epsilon() *
                     a.cwiseProduct(b).cwiseAbs().sum();
  EXPECT_NEAR(sum, a.dot(b), bound);
}

TEST(OwnedDofs, TheRFactorOverTheRanksRowsIsTheWholeMatrixs) {
  const mesh::Mesh<2> mesh = owned_dofs_channel();
  const Index n = mesh.n_nodes() * 2;
  const Index columns = 4;
  MatrixX tall(n, columns);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < columns; ++j)
      tall(i, j) = std::sin(0.3 * static_cast<Real>(i * (j + 1))) + (i % 7 == j ? 1.0 : 0.0);
  const int ranks = 3;
  // One process plays the ranks in turn; the sum over the ranks accumulates their
  // buffers, so the last rank's call sees every rank's R: its result is the whole one.
  std::vector<Real> accumulated;
  const auto accumulate = [&accumulated](std::span<Real> values) {
    accumulated.resize(values.size(), 0.0);
    for (std::size_t k = 0; k < values.size(); ++k) {
      accumulated[k] += values[k];
      values[k] = accumulated[k];
    }
  };
  MatrixX r;
  for (int rank = 0; rank < ranks; ++rank) {
    const FormingProblem<2> share(
        mesh, owned_dofs_settings({rank, ranks, accumulate, owned_dofs_interleaved()}));
    r = share.discretisation().owned_dofs().r_factor(tall);
  }
  ASSERT_EQ(r.rows(), columns);
  ASSERT_EQ(r.cols(), columns);
  for (Index i = 0; i < columns; ++i)
    for (Index j = 0; j < i; ++j) EXPECT_EQ(r(i, j), 0.0) << "R is upper triangular";
  // RᵀR = AᵀA up to two Householder QRs' backward error, O(n ε) relative to ‖A‖².
  const MatrixX gram = tall.transpose() * tall;
  const Real bound =
      8.0 * static_cast<Real>(n) * std::numeric_limits<Real>::epsilon() * tall.squaredNorm();
  EXPECT_LE((r.transpose() * r - gram).cwiseAbs().maxCoeff(), bound);
}

} // namespace
} // namespace formflow::assembly
