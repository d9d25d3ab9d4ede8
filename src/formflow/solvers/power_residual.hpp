// SPDX-License-Identifier: MIT
// The power of an iterate's residual: the part of the ram's load that is not balanced.
//
// Why exact friction's stop rule needs it (issue 16, docs/friction.md "Reaction and
// total power"): at a stuck point the traction is λ̂ + r u_T with r = 100/d_N = 1e8, so
// a traction change of O(1) is a velocity change of 1e-8, below what δ asks of the
// velocity. The Newton loop used to stop on the velocity change and the Coulomb residual
// alone while the stick/slip set still flipped from one iteration to the next, each flip
// leaving the free rows out of balance (axisymmetric Q2, sticking ram, h = 1, μ = 0.5,
// δ = 1e-8: ‖R_f‖ = 2.4 at the "converged" iterate, relative change 1e-9). The load then
// is wrong: with the internal force f(u) on every dof,
//     Σ_driven u_i f_i = u·f(u) − Σ_free u_i R_i,
// u·f(u) the total discrete power, so the ram reaction differs from the total power
// exactly by the residual's power (there 1e-4 relative: 5.77745 against 5.77693).
//
// Why the power and not ‖R_f‖: δ asks the load to δ, and this is the load's error
// (relative to the load, as the velocity change is relative to the velocity). A norm of
// R_f also asks for the tractions of stuck points inside near-rigid zones, which do no
// power (u_T = 0 there) and which this loop does not settle (measured: the loop stalls at
// δ = 1e-4 on 8 of the 60 Q2 cases with ‖R_f‖/‖f_driven‖ < δ asked, with every load
// right); their share of the reaction is what the power identity above accounts for.
#pragma once

#include "formflow/assembly/sparsity.hpp"
#include "formflow/core/types.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace formflow::solvers {

/// |Σ_free u_i f_i| / |Σ_driven u_i f_i| for the velocity u and internal force f (full
/// dof vectors; free rows of f: the residual): the relative difference between the
/// driven end's load and the total power that the residual makes. Dimensionless,
/// independent of the mesh's numbering and of units; zero in balance. Infinite when the
/// driven end does no power (nothing to compare with). `ghosted`: a distributed run's
/// problem, whose velocity each rank holds in part: both sums over the ranks' owned dofs
/// (NonlinearProblem::dot).
inline Real power_residual(const assembly::ScatterPlan& plan, const std::vector<Index>& driven_dofs,
                           const VectorX& velocity, const VectorX& internal_force,
                           const NonlinearProblem* ghosted = nullptr) {
  Real free_power = 0.0, driven_power = 0.0;
  if (ghosted) {
    free_power = ghosted->dot(plan.free_values(velocity), plan.free_values(internal_force));
    VectorX driven_velocity = VectorX::Zero(velocity.size());
    for (Index dof : driven_dofs) driven_velocity[dof] = velocity[dof];
    driven_power = ghosted->dot(driven_velocity, internal_force);
  } else {
    for (Index dof = 0; dof < plan.n_dofs(); ++dof)
      if (plan.free_index(dof) >= 0) free_power += velocity[dof] * internal_force[dof];
    for (Index dof : driven_dofs) driven_power += velocity[dof] * internal_force[dof];
  }
  if (!(std::abs(driven_power) > 0)) return std::numeric_limits<Real>::infinity();
  return std::abs(free_power / driven_power);
}

} // namespace formflow::solvers
