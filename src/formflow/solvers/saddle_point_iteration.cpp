// SPDX-License-Identifier: MIT
// Secant steps around a global saddle-point solve (continuous pressure, or a
// discontinuous one kept as a saddle point).
#include "formflow/solvers/saddle_point_iteration.hpp"

#include "formflow/assembly/contact_frames.hpp"
#include "formflow/assembly/rigid_body_modes.hpp"
#include "formflow/core/error.hpp"
#include "formflow/solvers/uzawa_update.hpp"

#include <algorithm>
#include <span>

namespace formflow::solvers {

template <int dim>
SaddlePointSolve<dim>::SaddlePointSolve(FormingNonlinearProblem<dim>& problem,
                                        TimedLinearStep& linear)
    : problem_(problem), linear_(linear), system_(problem.plan().make_system()) {
  const assembly::FormingProblem<dim>& forming = problem.forming();
  FF_ASSERT(forming.multipliers() && forming.multipliers()->has_global_pressure(),
            "a saddle-point solve needs a global pressure");
  ScopedTimer timer(linear.times(), "setup");
  saddle_.emplace(forming, *forming.multipliers());
  // For an iterative back-end (PETSc fieldsplit): the velocity/pressure split and
  // the velocity block's rigid-body modes, for its algebraic multigrid.
  linear.solver().set_fields(
      saddle_->n_velocity(),
      assembly::rigid_body_modes(forming.discretisation().mesh(), forming.plan()));
  // The contact penalty (1/d_N = 10⁶ by default) on an inclined die couples the
  // Cartesian components of every Γ3 node; in the node's normal–tangent frame it is one
  // diagonal entry, which AMG's smoothers resolve (docs/petsc.md).
  linear.solver().set_local_frames(assembly::contact_frames(forming.discretisation()));
  // Each velocity row's node, for an AMG that coarsens node by node (block size dim).
  const assembly::ScatterPlan& plan = forming.plan();
  std::vector<Index> dof_of_velocity(static_cast<std::size_t>(plan.n_free()));
  for (Index dof = 0; dof < plan.n_dofs(); ++dof)
    if (const Index row = plan.free_index(dof); row >= 0) dof_of_velocity[row] = dof;
  linear.solver().set_velocity_nodes(dim, std::move(dof_of_velocity));
  // A distributed run: each pressure dof's owner, the lowest rank among its cells
  // (replicate_pressure).
  const assembly::Discretisation<dim>& discretisation = forming.discretisation();
  if (discretisation.distribution().distributed()) {
    const std::vector<int>& cell_ranks = discretisation.cell_ranks();
    pressure_owner_.assign(static_cast<std::size_t>(saddle_->n_pressure()),
                           discretisation.distribution().size);
    for (Index cell = 0; cell < static_cast<Index>(cell_ranks.size()); ++cell)
      for (const Index dof : forming.multipliers()->cell_pressure_dofs(cell))
        pressure_owner_[dof] = std::min(pressure_owner_[dof], cell_ranks[cell]);
  }
}

/// One secant step at the lagged velocity `w` (null: constant viscosity):
/// factorise the saddle-point matrix once, solve for (u, δp), and with exact
/// contact repeat the solve after each multiplier update until they settle.
template <int dim> LaggedStep SaddlePointSolve<dim>::solve(const VectorX* w, VectorX& next) {
  assembly::ConstraintMultipliers<dim>& multipliers = *problem_.forming().multipliers();
  const assembly::Formulation& formulation = multipliers.formulation();
  const int max_steps = multipliers.is_exact_contact() ? formulation.uzawa_max_steps : 1;
  LaggedStep result{std::nullopt, false};
  UzawaSettling settling(formulation.uzawa_tolerance);
  assembly::SaddlePointSystem<dim>& saddle = *saddle_;
  for (int step = 0; step < max_steps; ++step) {
    {
      ScopedTimer timer(linear_.times(), "assembly");
      problem_.assemble_secant(w,
                               system_); // same matrix each step; the loads −Bᵀp, −λ_N v_N change
    }
    if (step == 0) {
      // The viscosities of this step's assembly scale the Schur preconditioner. Given
      // before the analysis: PETSc chooses its iterative default (and the velocity
      // block's node layout) from it at the first matrix it sees.
      linear_.solver().set_schur_preconditioner(saddle.schur_preconditioner(),
                                                saddle.pressure_block_size());
      // A back-end that keeps the blocks apart gets B and C once and A alone from then
      // on: the whole matrix, a copy of A with B beside it, is never built.
      if (!blocks_decided_) {
        blocks_decided_ = true;
        blocks_ =
            linear_.solver().take_saddle_point_blocks(saddle.coupling(), saddle.pressure_block());
      }
      if (!blocks_) saddle.fill_matrix(system_);
      const assembly::SparseMatrix& matrix = blocks_ ? system_.matrix : saddle.matrix();
      if (const auto stop = linear_.analyse_once(matrix)) return {stop, false};
      if (const auto stop = linear_.factorize(matrix)) return {stop, false};
    }
    const VectorX& pressure = multipliers.global_pressure();
    if (w && step == 0) {
      // The step's solution is (uⁿ⁺¹, δp): uⁿ and no correction is within the last
      // change of it, which an iterative back-end's Krylov method need not rebuild.
      VectorX guess = VectorX::Zero(saddle.n_velocity() + saddle.n_pressure());
      const assembly::ScatterPlan& plan = problem_.plan();
      for (Index dof = 0; dof < plan.n_dofs(); ++dof)
        if (const Index row = plan.free_index(dof); row >= 0) guess[row] = (*w)[dof];
      linear_.solver().set_initial_guess(std::move(guess));
    }
    VectorX solution;
    if (const auto stop = linear_.solve(saddle.rhs(system_, pressure), solution))
      return {stop, false};
    next = problem_.plan().expand(solution.head(saddle.n_velocity()), problem_.prescribed_values());
    VectorX increment = solution.tail(saddle.n_pressure());
    replicate_pressure(increment);
    VectorX next_pressure = pressure + increment;
    saddle.fix_pressure_level(next_pressure);
    // The reaction read from system() must include the new pressure's load.
    saddle.add_pressure_load(next_pressure - pressure, system_);
    multipliers.set_global_pressure(std::move(next_pressure));
    if (!multipliers.is_exact_contact()) {
      result.constraints_converged = true;
      break;
    }
    if (const auto stop = uzawa_update(problem_, next, settling, result.constraints_converged))
      return {stop, false};
    if (result.constraints_converged) break;
  }
  return result;
}

template <int dim> void SaddlePointSolve<dim>::replicate_pressure(VectorX& increment) const {
  const assembly::Distribution& distribution = problem_.forming().discretisation().distribution();
  if (!distribution.distributed()) return;
  // The solve hands each rank its own cells' pressure dofs (a ghosted solution); the
  // pressure is kept whole (the post-processing reads every cell's): each dof from its
  // owner, the others adding zeros.
  for (Index dof = 0; dof < increment.size(); ++dof)
    if (pressure_owner_[dof] != distribution.rank) increment[dof] = 0.0;
  distribution.sum_over_ranks(std::span<Real>(increment.data(), increment.size()));
}

template class SaddlePointSolve<2>;
template class SaddlePointSolve<3>;

} // namespace formflow::solvers
