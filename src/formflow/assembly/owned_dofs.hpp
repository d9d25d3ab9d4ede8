// SPDX-License-Identifier: MIT
// Which dofs a rank of a distributed run owns, and the two things a driver needs of
// vectors that each rank holds only in part (issue 20, docs/petsc.md "Distributed
// runs"): a dot product that counts every dof once, and the whole vector back.
//
// A distributed run's velocity is ghosted: each rank holds the entries of the dofs its
// own cells touch (the ones it owns and its ghosts), and the rest of its full-length
// vector is NaN, so that a loop which reads another rank's entry is loud, not quietly
// wrong. A dof is owned by the lowest rank whose cells touch it: the rule PETSc's rows
// follow (solvers/petsc/distributed_numbering.hpp), so a rank's owned entries are among
// those the solve hands it.
#pragma once

#include "formflow/assembly/distribution.hpp"
#include "formflow/assembly/sparsity.hpp"
#include "formflow/core/types.hpp"
#include "formflow/mesh/mesh.hpp"

#include <vector>

namespace formflow::assembly {

class OwnedDofs {
public:
  /// One rank: every dof is its own (n_owned() is left 0: not counted).
  OwnedDofs() = default;
  OwnedDofs(OwnedDofs&&) = default;
  OwnedDofs& operator=(OwnedDofs&&) = default;
  ~OwnedDofs();
  /// The dofs rank `distribution.rank` owns, from every cell's rank (`cell_ranks`, the
  /// same on every rank); `plan` numbers the free dofs.
  template <int dim>
  OwnedDofs(const mesh::Mesh<dim>& mesh, const std::vector<int>& cell_ranks,
            const ScatterPlan& plan, Distribution distribution);

  bool distributed() const { return distribution_.distributed(); }
  /// Whether this rank owns the (full-length numbering's) `dof`; always on one rank.
  bool owns(Index dof) const { return !distributed() || owned_full_[dof] != 0; }
  /// This rank's owned dofs, and its ghosts (the other dofs of its own cells, which it
  /// holds but another rank owns); one rank: every dof is owned, none a ghost.
  Index n_owned() const { return n_owned_; }
  Index n_ghosts() const { return n_ghosts_; }
  /// Σ aᵢ bᵢ over the dofs of full-length (n_dofs) or free (n_free) vectors; distributed:
  /// each rank sums its owned entries, then the ranks' sums are added (the same bits on
  /// every rank, Distribution::sum_over_ranks). Collective.
  Real dot(const VectorX& a, const VectorX& b) const;
  /// `values` (full-length or free) whole on every rank, each entry its owner's.
  /// Collective: O(n) traffic, for the end of a loop (the results) and for the few
  /// places that still read whole vectors (docs/petsc.md).
  void replicate(VectorX& values) const;
  /// The ranks' shares of `values` (full-length or free: each rank's own cells' part,
  /// zero elsewhere) added up: afterwards every entry the rank holds is the sum, the same
  /// bits on every rank that holds it, and the others are NaN (a ghosted vector).
  /// Through the ghost exchange (the interface's traffic); without one, summed whole.
  /// Collective.
  void sum_shares(VectorX& values) const;
  /// The R factor (c × c, upper triangular, RᵀR = AᵀA) of a tall matrix A of c
  /// full-length or free columns: each rank's QR of its owned rows, then the QR of the
  /// ranks' R's stacked (TSQR: a least-squares problem over the ranks as accurate as
  /// one QR of A, for c² numbers per rank). Collective; the same bits on every rank.
  MatrixX r_factor(const MatrixX& tall) const;

private:
  const std::vector<char>& mask_of(Index size) const;

  Distribution distribution_;
  std::vector<char> owned_full_; ///< per dof: this rank owns it
  std::vector<char> owned_free_; ///< per free dof
  Index n_owned_ = 0, n_ghosts_ = 0;
  /// The dofs this rank holds, owned (ascending) then ghosts (ascending): the order of
  /// the exchange's entries.
  std::vector<Index> held_;
  std::vector<Index> free_of_held_; ///< per held dof, its free index (−1: prescribed)
  std::unique_ptr<GhostExchange> exchange_;
};

} // namespace formflow::assembly
