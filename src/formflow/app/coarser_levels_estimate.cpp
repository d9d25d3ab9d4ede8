// SPDX-License-Identifier: MIT
// The "coarser" estimate: the loads on the structured channel at 2h and 4h.
#include "formflow/app/coarser_levels_estimate.hpp"

#include "formflow/app/estimate_levels.hpp"
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/post/load_error_estimate.hpp"

#include <fmt/format.h>

namespace formflow::app {

namespace {

/// The "coarser" estimate's cell indicators (empty when its adjoint cannot be solved):
/// the weighted residuals of the run's u against u_{2h} with the reaction's adjoint at
/// u on the run's mesh (post::weighted_residual_estimate; one factorisation there), each
/// 2h cell's share split evenly among its children. They sum to p_h − p_{2h} (both
/// fields converged: no linearisation), at the resolution of 2h: where the load's error
/// comes from, as the refined estimate's indicators say it at h.
template <int dim>
VectorX indicators_over_coarser(const RunPlan& plan, const assembly::FormingProblem<dim>& problem,
                                const VectorX& u, const SolvedLevel<dim>& coarser) {
  assembly::FormingProblem<dim> coarser_problem(coarser.mesh, plan.problem);
  const auto pressure = attached_pressure_multipliers(plan, coarser.mesh, coarser_problem);
  const std::vector<Index> parent = post::parent_cells(coarser.mesh, problem.mesh());
  const post::LoadErrorEstimate weighted = post::weighted_residual_estimate(
      coarser_problem, coarser.velocity, problem, u, parent, plan.solve.linear);
  if (!weighted.unavailable.empty()) return {};
  std::vector<int> children(static_cast<std::size_t>(coarser.mesh.n_cells()), 0);
  for (Index cell : parent) ++children[static_cast<std::size_t>(cell)];
  VectorX indicators(problem.mesh().n_cells());
  for (Index cell = 0; cell < indicators.size(); ++cell) {
    const Index coarse_cell = parent[static_cast<std::size_t>(cell)];
    indicators[cell] =
        weighted.cell_indicators[coarse_cell] / children[static_cast<std::size_t>(coarse_cell)];
  }
  return indicators;
}

} // namespace

template <int dim>
post::LoadErrorEstimate
coarser_levels_estimate(const RunPlan& plan, const assembly::FormingProblem<dim>& problem,
                        const VectorX& u, Real load, bool own_loop, PhaseTimes& times,
                        const IterationCallback& on_iteration) {
  ScopedTimer timer(times, "error estimate");
  const mesh::Mesh<dim>& mesh = problem.mesh();
  post::LoadErrorEstimate estimate;
  // A level on `level_mesh` from `start`, a field on it.
  const auto level = [&](const RunPlan& level_plan, mesh::Mesh<dim> level_mesh,
                         const VectorX& start, Index& iterations, std::string_view what) {
    const IterationCallback staged = level_stage(on_iteration, what, level_mesh);
    return own_loop
               ? solved_by_own_loop(level_plan, std::move(level_mesh), start, iterations, staged)
               : solved_level(level_plan, std::move(level_mesh), start, iterations, staged);
  };
  // The next coarser level from `from`'s velocity `field` restricted (interpolated).
  const auto coarsened = [&](Real size, const mesh::Mesh<dim>& from, const VectorX& field,
                             std::string_view what) {
    mesh::Mesh<dim> level_mesh = channel_at<dim>(plan, size);
    const VectorX start = fem::interpolate_nodal_field(from, field, dim, level_mesh);
    return level(plan, std::move(level_mesh), start, estimate.coarser_newton_iterations, what);
  };
  const std::optional<SolvedLevel<dim>> coarser =
      coarsened(2 * plan.mesh.size, mesh, u, "the mesh coarsened once (2h)");
  if (!coarser) return no_estimate("the solve on the mesh coarsened once (2h) did not converge");
  const std::optional<SolvedLevel<dim>> coarsest = coarsened(
      4 * plan.mesh.size, coarser->mesh, coarser->velocity, "the mesh coarsened twice (4h)");
  if (!coarsest) return no_estimate("the solve on the mesh coarsened twice (4h) did not converge");
  const Real change = load - coarser->load;
  const Real coarsest_change = coarser->load - coarsest->load;
  estimate.method = "coarser";
  estimate.coarser_change = change;
  estimate.coarsest_change = coarsest_change;
  const Real observed = change / coarsest_change; // ±inf or NaN: refused by tail_ratio
  const std::optional<Real> ratio = post::tail_ratio(observed);
  if (!ratio)
    return no_estimate(fmt::format(
        "the loads on 4h, 2h, h do not converge monotonically (p_h − p_2h = {:.4g}, p_2h − "
        "p_4h = {:.4g}): no tail can be summed; \"refined\" estimates from h/2",
        change, coarsest_change));
  estimate.observed_ratio = observed;
  estimate.ratio = *ratio;
  estimate.discretisation_error = post::tail_beyond_refined(change, *ratio);
  const std::optional<SolvedLevel<dim>> doubled =
      level(doubled_regularisations(plan), coarser->mesh, coarser->velocity,
            estimate.penalty_newton_iterations, "the regularisations doubled on 2h");
  if (!doubled) {
    estimate.unavailable =
        "the run with doubled regularisations (d, d_N, d_T, α) on 2h did not converge";
    return estimate;
  }
  estimate.penalty_change = doubled->load - coarser->load;
  estimate.error = post::coarser_levels_bound(change, *ratio, *estimate.penalty_change);
  if (!own_loop) estimate.cell_indicators = indicators_over_coarser(plan, problem, u, *coarser);
  return estimate;
}

template post::LoadErrorEstimate coarser_levels_estimate<2>(const RunPlan&,
                                                            const assembly::FormingProblem<2>&,
                                                            const VectorX&, Real, bool, PhaseTimes&,
                                                            const IterationCallback&);
template post::LoadErrorEstimate coarser_levels_estimate<3>(const RunPlan&,
                                                            const assembly::FormingProblem<3>&,
                                                            const VectorX&, Real, bool, PhaseTimes&,
                                                            const IterationCallback&);

} // namespace formflow::app
