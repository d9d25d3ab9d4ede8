// SPDX-License-Identifier: MIT
// L Lᵀ x = b with a CHOLMOD supernodal factor, independent subtrees on separate threads.
#pragma once

#include "formflow/core/types.hpp"

#include <cholmod.h>

#include <vector>

namespace formflow::solvers {

/// The two triangular solves with CHOLMOD's supernodal LLᵀ factor of a matrix in its
/// natural order (solvers/cholmod.cpp factorises P A Pᵀ so), the elimination tree's
/// independent subtrees in two bins solved at the same time.
///
/// Why not cholmod_solve: CHOLMOD's supernodal solve is one sweep on one thread
/// (dtrsv and dgemv per supernode), and in Newton's GMRES (one solve per Krylov
/// iteration, T⁻¹ as the preconditioner) it was 15 % of the adaptive sticking ram's
/// wall time. A supernode's off-diagonal rows belong to its ancestors only, so the
/// subtrees below the top of the tree write to their own rows and, in the forward
/// sweep, to the top's rows: each bin adds its updates of those into a buffer of its
/// own, and the buffers are added in bin order. The bins are fixed by the tree, never by
/// the thread count: one thread runs the same operations in the same order (the results
/// are bit for bit the same on any number of threads; they differ from CHOLMOD's sweep
/// by round-off in the order of the top's updates).
class SupernodalSolve {
public:
  SupernodalSolve() = default;
  /// The schedule of `factor`'s supernodes (its symbolic analysis suffices).
  explicit SupernodalSolve(const cholmod_factor& factor);

  /// x ← (L Lᵀ)⁻¹ x with the numeric `factor` the schedule was made for.
  void solve(const cholmod_factor& factor, Real* x) const;

  /// The share of the solve's work in the two bins (the rest is the top's, serial).
  double parallel_share() const { return parallel_share_; }

private:
  static constexpr int bins = 2;
  std::vector<Index> bin_supernodes_[bins]; ///< ascending: children before parents
  std::vector<Index> top_supernodes_;       ///< ascending
  std::vector<Index> top_rows_;             ///< the rows of the top's supernodes
  std::vector<Index> top_slot_;             ///< row → its slot in top_rows_, or −1
  double parallel_share_ = 0;
  double factor_nonzeros_ = 0; ///< Σ rows × columns of the supernodes
};

} // namespace formflow::solvers
