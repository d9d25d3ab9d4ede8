// SPDX-License-Identifier: MIT
// The force balance of an iterate: what the velocity change cannot see at stuck points.
//
// Why exact friction's stop rule needs it (issue 16, docs/friction.md "Reaction and
// total power"): at a stuck point the traction is λ̂ + r u_T with r = 100/d_N = 1e8, so
// a change of the traction by O(1) is a change of u by 1e-8 — below what δ asks of the
// velocity. The Newton loop used to stop on the velocity change and the Coulomb residual
// alone while the stick/slip set still flipped from one iteration to the next; each flip
// left the free rows out of balance by O(1) (axisymmetric Q2, sticking ram, h = 1,
// μ = 0.5, δ = 1e-8: ‖R_f‖ = 2.4 at the "converged" iterate, relative change 1e-9), and
// the ram reaction then differed from the total power by 1e-4 (the power identity
// u⁰ Σ_driven f = u·f(u) − u_f·R_f holds only in balance).
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/core/types.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace formflow::solvers {

/// ‖R_f‖ / ‖f_driven‖: the residual on the free rows of an internal force (full dof
/// vector) relative to the nodal forces on the driven dofs (the ram), both Euclidean
/// norms of nodal forces, so the ratio does not change with the mesh size for a given
/// traction error, nor with the units of force. Infinite when the driven force is zero
/// (nothing to compare with: never "balanced").
inline Real force_imbalance(const assembly::ScatterPlan& plan,
                            const std::vector<Index>& driven_dofs, const VectorX& internal_force) {
  Real free_norm = 0.0, driven_norm = 0.0;
  for (Index dof = 0; dof < plan.n_dofs(); ++dof)
    if (plan.free_index(dof) >= 0) free_norm += internal_force[dof] * internal_force[dof];
  for (Index dof : driven_dofs) driven_norm += internal_force[dof] * internal_force[dof];
  if (!(driven_norm > 0)) return std::numeric_limits<Real>::infinity();
  return std::sqrt(free_norm / driven_norm);
}

} // namespace formflow::solvers
