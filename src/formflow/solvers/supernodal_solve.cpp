// SPDX-License-Identifier: MIT
// SupernodalSolve: the tree's subtrees in two bins, the top serial, Eigen's kernels per supernode.
#include "formflow/solvers/supernodal_solve.hpp"

#include "formflow/core/error.hpp"
#include "formflow/core/parallel_tasks.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <numeric>
#include <queue>

namespace formflow::solvers {

namespace {

/// A supernode's layout in CHOLMOD's arrays: columns [first, first + columns), rows
/// (the first `columns` of them its own columns) and values (rows × columns, column major).
struct Supernode {
  Index first, columns, rows;
  const Index* row_index;
  const Real* values;
};

Supernode supernode(const cholmod_factor& factor, Index s) {
  const Index* super = static_cast<const Index*>(factor.super);
  const Index* pi = static_cast<const Index*>(factor.pi);
  const Index* px = static_cast<const Index*>(factor.px);
  const Index* rows = static_cast<const Index*>(factor.s);
  const Real* x = static_cast<const Real*>(factor.x);
  return {super[s], super[s + 1] - super[s], pi[s + 1] - pi[s], rows + pi[s],
          x ? x + px[s] : nullptr};
}

/// Factor entries (rows × columns over the supernodes) from which the bins run on two
/// threads: below, a solve takes less than about 0.2 ms, and waking a helper thread (twice
/// per solve) would cost a fair part of that.
constexpr double threaded_factor_nonzeros = 2e5;

using Block =
    Eigen::Map<const Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>, 0, Eigen::OuterStride<>>;

Block diagonal_block(const Supernode& node) {
  return Block(node.values, node.columns, node.columns, Eigen::OuterStride<>(node.rows));
}
Block below_block(const Supernode& node) {
  return Block(node.values + node.columns, node.rows - node.columns, node.columns,
               Eigen::OuterStride<>(node.rows));
}

/// Forward: x_s ← L_ss⁻¹ x_s, then the rows below lose L_bs x_s; a row of the top goes
/// to `top_updates` (its slot) when given, else to x.
void forward(const Supernode& node, Real* x, const std::vector<Index>* top_slot, Real* top_updates,
             Real* buffer) {
  Eigen::Map<Eigen::VectorXd> own(x + node.first, node.columns);
  diagonal_block(node).triangularView<Eigen::Lower>().solveInPlace(own);
  const Index below = node.rows - node.columns;
  if (below == 0) return;
  Eigen::Map<Eigen::VectorXd> work(buffer, below);
  work.noalias() = below_block(node) * own;
  for (Index k = 0; k < below; ++k) {
    const Index row = node.row_index[node.columns + k];
    const Index slot = top_slot ? (*top_slot)[row] : -1;
    if (slot >= 0)
      top_updates[slot] -= work[k];
    else
      x[row] -= work[k];
  }
}

/// Backward: x_s loses L_bsᵀ x_b, then x_s ← L_ssᵀ⁻¹ x_s.
void backward(const Supernode& node, Real* x, Real* buffer) {
  Eigen::Map<Eigen::VectorXd> own(x + node.first, node.columns);
  const Index below = node.rows - node.columns;
  if (below > 0) {
    Eigen::Map<Eigen::VectorXd> work(buffer, below);
    for (Index k = 0; k < below; ++k) work[k] = x[node.row_index[node.columns + k]];
    own.noalias() -= below_block(node).transpose() * work;
  }
  diagonal_block(node).transpose().triangularView<Eigen::Upper>().solveInPlace(own);
}

} // namespace

SupernodalSolve::SupernodalSolve(const cholmod_factor& factor) {
  FF_ASSERT(factor.is_super && factor.itype == CHOLMOD_INT, "a supernodal factor, int indices");
  const Index n_super = static_cast<Index>(factor.nsuper);
  const Index* super = static_cast<const Index*>(factor.super);
  // The supernodal tree: a supernode's parent holds its first row below its columns.
  std::vector<Index> owner(factor.n);
  for (Index s = 0; s < n_super; ++s)
    for (Index column = super[s]; column < super[s + 1]; ++column) owner[column] = s;
  std::vector<Index> parent(n_super, -1);
  std::vector<double> weight(n_super), subtree(n_super);
  std::vector<std::vector<Index>> children(n_super);
  std::vector<Index> roots;
  for (Index s = 0; s < n_super; ++s) {
    const Supernode node = supernode(factor, s);
    weight[s] = static_cast<double>(node.rows) * node.columns; // the solve's work there
    if (node.rows > node.columns) {
      parent[s] = owner[node.row_index[node.columns]];
      children[parent[s]].push_back(s);
    } else {
      roots.push_back(s);
    }
  }
  // Children come before parents (a parent's first column is past its child's rows).
  for (Index s = 0; s < n_super; ++s) {
    subtree[s] += weight[s];
    if (parent[s] >= 0) subtree[parent[s]] += subtree[s];
  }
  const double total = std::accumulate(weight.begin(), weight.end(), 0.0);
  // Open the heaviest subtree into its children (its root joins the top) until the two
  // bins can be balanced: the heaviest subtree at most half of the subtrees' weight.
  std::vector<bool> in_top(n_super, false);
  auto heavier = [&](Index a, Index b) {
    return subtree[a] < subtree[b] || (subtree[a] == subtree[b] && a < b);
  };
  std::priority_queue<Index, std::vector<Index>, decltype(heavier)> open(heavier, roots);
  double open_weight = total;
  while (!open.empty() && subtree[open.top()] > 0.5 * open_weight && open_weight > 0.5 * total) {
    const Index s = open.top();
    open.pop();
    in_top[s] = true;
    open_weight -= weight[s];
    for (const Index child : children[s]) open.push(child);
  }
  // The subtrees, heaviest first, each into the lighter bin (ties by number).
  std::vector<Index> subtree_roots;
  while (!open.empty()) subtree_roots.push_back(open.top()), open.pop();
  std::vector<int> bin_of(n_super, -1);
  double load[bins] = {0, 0};
  for (const Index root : subtree_roots) {
    const int bin = load[1] < load[0] ? 1 : 0;
    load[bin] += subtree[root];
    bin_of[root] = bin;
  }
  // Every supernode below the top takes its subtree root's bin (parents after children:
  // descend from the top down by scanning the numbers backwards).
  for (Index s = n_super - 1; s >= 0; --s)
    if (!in_top[s] && bin_of[s] < 0) bin_of[s] = parent[s] >= 0 ? bin_of[parent[s]] : 0;
  top_slot_.assign(factor.n, -1);
  for (Index s = 0; s < n_super; ++s) {
    if (in_top[s]) {
      top_supernodes_.push_back(s);
      for (Index column = super[s]; column < super[s + 1]; ++column) {
        top_slot_[column] = static_cast<Index>(top_rows_.size());
        top_rows_.push_back(column);
      }
    } else {
      bin_supernodes_[bin_of[s]].push_back(s);
    }
  }
  parallel_share_ = total > 0 ? (load[0] + load[1]) / total : 0.0;
  factor_nonzeros_ = total;
}

void SupernodalSolve::solve(const cholmod_factor& factor, Real* x) const {
  const std::size_t n_top = top_rows_.size();
  std::vector<Real> top_updates[bins];
  // Threads pay from a factor of some size on (a helper woken twice per solve).
  const std::size_t threads = factor_nonzeros_ >= threaded_factor_nonzeros
                                  ? std::min<std::size_t>(compute_threads(), bins)
                                  : 1;
  // Forward: the bins (their updates of the top's rows apart), then the top.
  run_tasks(bins, threads, [&](std::size_t bin) {
    top_updates[bin].assign(n_top, 0.0);
    std::vector<Real> work(factor.maxesize);
    for (const Index s : bin_supernodes_[bin])
      forward(supernode(factor, s), x, &top_slot_, top_updates[bin].data(), work.data());
  });
  for (int bin = 0; bin < bins; ++bin)
    for (std::size_t k = 0; k < n_top; ++k) x[top_rows_[k]] += top_updates[bin][k];
  std::vector<Real> work(factor.maxesize);
  for (const Index s : top_supernodes_)
    forward(supernode(factor, s), x, nullptr, nullptr, work.data());
  // Backward: the top (descending), then the bins (each descending) at the same time.
  for (auto s = top_supernodes_.rbegin(); s != top_supernodes_.rend(); ++s)
    backward(supernode(factor, *s), x, work.data());
  run_tasks(bins, threads, [&](std::size_t bin) {
    std::vector<Real> bin_work(factor.maxesize);
    for (auto s = bin_supernodes_[bin].rbegin(); s != bin_supernodes_[bin].rend(); ++s)
      backward(supernode(factor, *s), x, bin_work.data());
  });
}

} // namespace formflow::solvers
