// SPDX-License-Identifier: MIT
// A Newton step condensed onto exact linear constraints (exact friction's u_T = 0 at
// the stuck Γ3 nodes: the semismooth Newton of issue 16).
//
// Why a condensation and not a saddle point: with one multiplier per Γ3 node (nodal
// contact points) the stick constraints c_k·δ = g_k are orthonormal vectors on the
// free dofs of one node each. Writing δ = g + z with g = Σ g_k c_k and z in the range
// of P = I − Σ c_k c_kᵀ, the step solves
//     (P J P + Σ α_k c_k c_kᵀ) z = −P (R + J g),
// whose matrix has the pattern of J (P only mixes the dofs of one node, and a node's
// dofs are coupled in every cell it belongs to), is symmetric positive definite where
// J's symmetric part is (the added α_k = c_kᵀ T c_k > 0 keep the constrained directions
// at the stiffness they had, so the factorisation's conditioning is not spoiled), and so
// goes to the same CHOLMOD analysis; the unsymmetric rest P N P stays matrix free for
// GMRES. A saddle point [J Bᵀ; B 0] would need UMFPACK and a new pattern each time the
// active set changes. The multiplier of constraint k is the reaction c_k·(R + J δ) it
// supplies, read off the full system after the step.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"

#include <vector>

namespace formflow::solvers {

class StepCondensation {
public:
  /// `constraints` orthonormal (rows of different constraints of one node may overlap,
  /// their coefficient vectors are orthogonal), on a free system of size `n_free`.
  StepCondensation(std::vector<StepConstraint> constraints, Index n_free);

  /// `condensed` (which must have `lower`'s pattern) = lower triangle of P T P + Σ α_k c_k c_kᵀ
  /// for T given by its lower triangle `lower`.
  void condense(const assembly::SparseMatrix& lower, assembly::SparseMatrix& condensed) const;
  /// P x.
  VectorX project(const VectorX& x) const;
  /// g = Σ g_k c_k: the step's part along the constraints.
  VectorX particular() const;
  /// c_k·x for every constraint.
  std::vector<Real> components(const VectorX& x) const;

private:
  std::vector<StepConstraint> constraints_;
  Index n_free_;
};

} // namespace formflow::solvers
