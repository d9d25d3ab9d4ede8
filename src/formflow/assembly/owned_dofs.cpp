// SPDX-License-Identifier: MIT
#include "formflow/assembly/owned_dofs.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/dof_map.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <limits>
#include <span>

namespace formflow::assembly {

template <int dim>
OwnedDofs::OwnedDofs(const mesh::Mesh<dim>& mesh, const std::vector<int>& cell_ranks,
                     const ScatterPlan& plan, Distribution distribution)
    : distribution_(std::move(distribution)) {
  if (!distribution_.distributed()) return;
  FF_ASSERT(static_cast<Index>(cell_ranks.size()) == mesh.n_cells(), "a rank for every cell");
  // The lowest rank among the cells around each node (a node's dofs go together).
  std::vector<int> owner(static_cast<std::size_t>(mesh.n_nodes()), std::numeric_limits<int>::max());
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    for (Index k = 0; k < mesh.cells.rows(); ++k) {
      int& node_owner = owner[mesh.cells(k, cell)];
      node_owner = std::min(node_owner, cell_ranks[cell]);
    }
  owned_full_.assign(static_cast<std::size_t>(mesh.n_nodes()) * dim, 0);
  owned_free_.assign(static_cast<std::size_t>(plan.n_free()), 0);
  std::vector<char> touched(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (Index cell = 0; cell < mesh.n_cells(); ++cell)
    if (cell_ranks[cell] == distribution_.rank)
      for (Index k = 0; k < mesh.cells.rows(); ++k) touched[mesh.cells(k, cell)] = 1;
  // The global numbering the exchange uses: each rank's owned dofs consecutively, ranks
  // in order, ascending within a rank (every rank computes it alike, without a message).
  std::vector<Index> first(static_cast<std::size_t>(distribution_.size) + 1, 0);
  for (Index node = 0; node < mesh.n_nodes(); ++node) first[owner[node] + 1] += dim;
  for (int r = 0; r < distribution_.size; ++r) first[r + 1] += first[r];
  std::vector<Index> next(first.begin(), first.end() - 1);
  std::vector<Index> ghosts, ghost_globals;
  for (Index node = 0; node < mesh.n_nodes(); ++node)
    for (int i = 0; i < dim; ++i) {
      const Index global = next[owner[node]]++;
      const Index dof = fem::dof_of<dim>(node, i);
      if (owner[node] == distribution_.rank) {
        held_.push_back(dof);
        owned_full_[dof] = 1;
        if (const Index free = plan.free_index(dof); free >= 0) owned_free_[free] = 1;
      } else if (touched[node]) {
        ghosts.push_back(dof);
        ghost_globals.push_back(global);
      }
    }
  n_owned_ = static_cast<Index>(held_.size());
  n_ghosts_ = static_cast<Index>(ghosts.size());
  held_.insert(held_.end(), ghosts.begin(), ghosts.end());
  for (const Index dof : held_) free_of_held_.push_back(plan.free_index(dof));
  if (distribution_.make_ghost_exchange)
    exchange_ = distribution_.make_ghost_exchange(n_owned_, ghost_globals);
}

const std::vector<char>& OwnedDofs::mask_of(Index size) const {
  FF_ASSERT(size == static_cast<Index>(owned_full_.size()) ||
                size == static_cast<Index>(owned_free_.size()),
            "a full-length or a free dof vector");
  return size == static_cast<Index>(owned_full_.size()) ? owned_full_ : owned_free_;
}

Real OwnedDofs::dot(const VectorX& a, const VectorX& b) const {
  FF_ASSERT(a.size() == b.size(), "two vectors of one length");
  if (!distributed()) return a.dot(b);
  const std::vector<char>& owned = mask_of(a.size());
  Real sum = 0.0;
  for (Index i = 0; i < a.size(); ++i)
    if (owned[i]) sum += a[i] * b[i];
  distribution_.sum_over_ranks(std::span<Real>(&sum, 1));
  return sum;
}

OwnedDofs::~OwnedDofs() = default;

void OwnedDofs::sum_shares(VectorX& values) const {
  if (!distributed()) return;
  if (!exchange_) {
    distribution_.sum_over_ranks(std::span<Real>(values.data(), values.size()));
    return;
  }
  const bool free = values.size() != static_cast<Index>(owned_full_.size());
  FF_ASSERT(!free || values.size() == static_cast<Index>(owned_free_.size()),
            "a full-length or a free dof vector");
  std::vector<Real> held(held_.size(), 0.0);
  for (std::size_t k = 0; k < held_.size(); ++k) {
    const Index index = free ? free_of_held_[k] : held_[k];
    if (index >= 0) held[k] = values[index];
  }
  exchange_->sum_shares(held);
  values.setConstant(std::numeric_limits<Real>::quiet_NaN());
  for (std::size_t k = 0; k < held_.size(); ++k) {
    const Index index = free ? free_of_held_[k] : held_[k];
    if (index >= 0) values[index] = held[k];
  }
}

void OwnedDofs::replicate(VectorX& values) const {
  if (!distributed()) return;
  const std::vector<char>& owned = mask_of(values.size());
  for (Index i = 0; i < values.size(); ++i)
    if (!owned[i]) values[i] = 0.0; // x + 0 is x: each entry comes out as its owner's bits
  distribution_.sum_over_ranks(std::span<Real>(values.data(), values.size()));
}

namespace {

/// The upper triangle of A's Householder QR, c × c (zero rows below A's own rank).
MatrixX upper_factor(const MatrixX& a) {
  const Index c = a.cols();
  MatrixX r = MatrixX::Zero(c, c);
  if (a.rows() == 0) return r;
  const Eigen::HouseholderQR<MatrixX> qr(a);
  const Index rows = std::min<Index>(a.rows(), c);
  r.topRows(rows) = qr.matrixQR().topRows(rows).template triangularView<Eigen::Upper>();
  return r;
}

} // namespace

MatrixX OwnedDofs::r_factor(const MatrixX& tall) const {
  if (!distributed()) return upper_factor(tall);
  const std::vector<char>& owned = mask_of(tall.rows());
  Index n_owned = 0;
  for (const char o : owned) n_owned += o ? 1 : 0;
  MatrixX mine(n_owned, tall.cols());
  for (Index i = 0, row = 0; i < tall.rows(); ++i)
    if (owned[i]) mine.row(row++) = tall.row(i);
  const Index c = tall.cols();
  // Every rank's R in its slot of one buffer: the sum over the ranks gathers them.
  MatrixX stacked = MatrixX::Zero(c * distribution_.size, c);
  stacked.middleRows(c * distribution_.rank, c) = upper_factor(mine);
  distribution_.sum_over_ranks(std::span<Real>(stacked.data(), stacked.size()));
  return upper_factor(stacked);
}

template OwnedDofs::OwnedDofs(const mesh::Mesh<2>&, const std::vector<int>&, const ScatterPlan&,
                              Distribution);
template OwnedDofs::OwnedDofs(const mesh::Mesh<3>&, const std::vector<int>&, const ScatterPlan&,
                              Distribution);

} // namespace formflow::assembly
