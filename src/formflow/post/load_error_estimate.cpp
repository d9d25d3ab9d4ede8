// SPDX-License-Identifier: MIT
// The reaction's adjoint on the mesh refined once and its cell-wise weighted residuals.
#include "formflow/post/load_error_estimate.hpp"

#include "formflow/core/error.hpp"
#include "formflow/fem/nodal_interpolation.hpp"
#include "formflow/solvers/coupled_tangent_solve.hpp"
#include "formflow/solvers/forming_nonlinear_problem.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/newton_iteration.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <span>

namespace formflow::post {

namespace {

/// The settle on the refined mesh stops on the load once two successive Newton
/// iterations have each moved it by at most this fraction of its change from p_h
/// (the change the estimate measures), or at the case's δ, whichever comes first.
/// Why the load and not the velocity: the estimate needs p_{h/2} − p_h, and the DWR
/// identity Q(ũ) − z·R(ũ) corrects the remaining residual to first order, so the
/// velocity's last digits (the last 4–6 iterations of a δ = 1e-4 … 1e-8 settle move
/// the load by < 1e-6 on the benchmark) buy nothing; 1 % of the change keeps the
/// change's error far below the 25 % the safety factor adds (and the adaptive run's
/// end on the refined mesh is checked with the direct change, solved there to δ).
constexpr Real settle_load_fraction = 1e-2;

/// GMRES tolerance for (T + Nᵀ) z = g: the adjoint's relative error enters the
/// estimate linearly, so 1e-6 is far below the two digits an error bar needs.
constexpr Real adjoint_tolerance = 1e-6;
constexpr int max_adjoint_krylov_iterations = 40;

/// ∂Q/∂u on the free dofs: the driven rows of the full Jacobian summed, Jᵀ_{D,f} 1.
/// T is symmetric and its prescribed rows are `reaction_rows`; Nᵀ 1_D adds the
/// unsymmetric rest.
template <int dim>
VectorX reaction_gradient(const assembly::FormingProblem<dim>& problem,
                          const assembly::LinearSystem& tangent,
                          const assembly::UnsymmetricTangent<dim>& coupling) {
  const assembly::ScatterPlan& plan = problem.plan();
  VectorX driven = VectorX::Zero(problem.n_dofs());
  for (Index dof : problem.constraints().driven_dofs) driven[dof] = 1.0;
  // Σ over the driven rows of T's constrained rows (n_constrained × n_dofs).
  VectorX row_weights = VectorX::Zero(plan.n_prescribed());
  for (Index dof : problem.constraints().driven_dofs) row_weights[plan.prescribed_index(dof)] = 1.0;
  const VectorX full_gradient_t = tangent.reaction_rows.transpose() * row_weights;
  VectorX full_gradient = full_gradient_t;
  if (!coupling.empty()) problem.apply_coupling_transpose(coupling, driven, full_gradient);
  // A distributed run's rows and coupling are the rank's shares: their sum, ghosted.
  problem.discretisation().owned_dofs().sum_shares(full_gradient);
  VectorX gradient(plan.n_free());
  for (Index dof = 0; dof < plan.n_dofs(); ++dof)
    if (const Index free = plan.free_index(dof); free >= 0) gradient[free] = full_gradient[dof];
  return gradient;
}

LoadErrorEstimate unavailable(std::string why) {
  LoadErrorEstimate estimate;
  estimate.unavailable = std::move(why);
  return estimate;
}

} // namespace

template <int dim>
LoadErrorEstimate
weighted_residual_estimate(const assembly::FormingProblem<dim>& coarse, const VectorX& u,
                           const assembly::FormingProblem<dim>& fine, const VectorX& fine_velocity,
                           const std::vector<Index>& parent, solvers::LinearSolverKind kind,
                           solvers::LinearSolver* analysed) {
  const assembly::ScatterPlan& plan = fine.plan();
  const std::vector<Real> thresholds = fine.friction_thresholds(fine_velocity);

  // 2. The exact Jacobian at ũ (primal: no duals) and the adjoint.
  assembly::LinearSystem tangent = plan.make_system();
  assembly::UnsymmetricTangent<dim> coupling;
  VectorX force;
  fine.assemble_newton(fine_velocity, thresholds, assembly::NewtonDuals<dim>{}, force, &tangent,
                       &coupling);
  // Whether any rank's cells hold a coupling (and friction in it): the branches below
  // are taken alike on every rank. A rank whose own cells hold none (a rigid part) must
  // still join the others' GMRES, whose every product is collective (the paper case at
  // h = 0.5 on 5 ranks waited for ever with one rank in a direct solve).
  std::array<Real, 2> anywhere = {coupling.empty() ? 0.0 : 1.0, coupling.has_friction ? 1.0 : 0.0};
  if (const assembly::Distribution& distribution = fine.discretisation().distribution();
      distribution.distributed())
    distribution.sum_over_ranks(std::span<Real>(anywhere));
  const bool uncoupled = anywhere[0] == 0;
  if (anywhere[1] > 0 && fine.multipliers())
    return unavailable("a pressure-dependent friction threshold with constraint multipliers "
                       "(the mixed formulation) couples the tangent through a contact pressure "
                       "whose transpose is not implemented");
  const VectorX gradient = reaction_gradient(fine, tangent, coupling);
  // Distributed (issue 20): the gradient is summed (ghosted), the tangent and coupling
  // are shares; the adjoint comes back ghosted and is made whole for the weights.
  const assembly::OwnedDofs& owned = fine.discretisation().owned_dofs();
  // (T + Nᵀ) z = g by GMRES preconditioned with a factor of T (T symmetric: only N is
  // transposed; without N the factor of T itself solves it exactly).
  const solvers::CouplingProduct transposed = [&](const VectorX& x, VectorX& y) {
    if (coupling.empty()) return;
    const VectorX full_x = plan.expand(x, VectorX::Zero(plan.n_dofs()));
    VectorX full_y = VectorX::Zero(plan.n_dofs());
    fine.apply_coupling_transpose(coupling, full_x, full_y);
    for (Index dof = 0; dof < plan.n_dofs(); ++dof)
      if (const Index free = plan.free_index(dof); free >= 0) y[free] += full_y[dof];
  };
  solvers::ShareSum add_up_shares;
  solvers::GhostedDot dot;
  if (owned.distributed()) {
    add_up_shares = [&owned](VectorX& values) { owned.sum_shares(values); };
    dot = [&owned](const VectorX& a, const VectorX& b) { return owned.dot(a, b); };
  }
  // `exact`: the factor is of T(ũ) itself, not of a nearby tangent.
  const auto solve_adjoint = [&](solvers::LinearSolver& factorized, bool exact, VectorX& adjoint) {
    if (uncoupled && exact)
      return factorized.solve_whole(gradient, adjoint) && factorized.finite(adjoint);
    const solvers::KrylovOutcome krylov = solvers::solve_coupled_tangent(
        tangent.matrix, transposed, factorized, gradient, adjoint, adjoint_tolerance,
        max_adjoint_krylov_iterations, add_up_shares, dot);
    return krylov.converged && std::isfinite(owned.dot(adjoint, adjoint));
  };
  VectorX adjoint;
  // The settle's solver still holds the factor of its last Newton step, one step from ũ:
  // GMRES with it as the preconditioner of the exact J(ũ) saves the factorisation at ũ
  // (measured on the adaptive ram's split meshes: 10–24 Krylov iterations instead of
  // 4–7, all converged; a factorisation costs tens of them). If it does not converge,
  // the tangent at ũ is factorised as without a settle. CHOLMOD's only: a direct factor
  // (an iterative back-end's preconditioner is set up for its own matrix).
  bool solved = false;
  if (analysed && kind == solvers::LinearSolverKind::Cholmod) {
    analysed->set_solve_tolerance(0.0); // an iterative back-end's own tolerance again
    solved = solve_adjoint(*analysed, false, adjoint);
  }
  if (!solved) {
    std::unique_ptr<solvers::LinearSolver> own_solver;
    solvers::LinearSolver* solver = analysed;
    if (!solver) {
      own_solver = solvers::make_linear_solver(kind, solvers::MatrixStorage::SymmetricLower);
      solver = own_solver.get();
      if (!solver->analyze(tangent.matrix))
        return unavailable("the tangent on the refined mesh is not positive definite");
    }
    if (!solver->factorize(tangent.matrix))
      return unavailable("the tangent on the refined mesh is not positive definite");
    if (!solve_adjoint(*solver, true, adjoint))
      return unavailable(uncoupled ? "the adjoint solve on the refined mesh failed"
                                   : "GMRES on the transposed tangent did not converge");
  }
  owned.replicate(adjoint);
  if (!adjoint.allFinite()) return unavailable("the adjoint is not finite");

  // 3. The weights W (fine) and W_h (its values at the coarse nodes) and the cells' shares.
  VectorX weight = plan.expand(-adjoint, VectorX::Zero(plan.n_dofs()));
  for (Index dof : fine.constraints().driven_dofs) weight[dof] = 1.0;
  const VectorX coarse_weight =
      fem::interpolate_nodal_field(fine.mesh(), weight, dim, coarse.mesh());
  const VectorX fine_shares = fine.weighted_cell_forces(fine_velocity, thresholds, weight);
  LoadErrorEstimate estimate;
  estimate.cell_indicators =
      -coarse.weighted_cell_forces(u, coarse.friction_thresholds(u), coarse_weight);
  FF_ASSERT(static_cast<Index>(parent.size()) == fine.mesh().n_cells(), "one parent per fine cell");
  for (Index cell = 0; cell < fine.mesh().n_cells(); ++cell)
    estimate.cell_indicators[parent[cell]] += fine_shares[cell];
  const Real height = coarse.driven_height();
  estimate.cell_indicators /= height;
  estimate.enriched_change = estimate.cell_indicators.sum();
  estimate.enriched_dofs = fine.n_dofs();
  if (!std::isfinite(estimate.enriched_change) || !estimate.cell_indicators.allFinite())
    return unavailable("the weighted residual is not finite");
  return estimate;
}

template <int dim>
LoadErrorEstimate
estimate_load_error(const assembly::FormingProblem<dim>& coarse, const VectorX& u,
                    const assembly::FormingProblem<dim>& fine, const std::vector<Index>& parent,
                    solvers::LinearSolverKind kind, const solvers::IterationControl* settle,
                    PhaseTimes& times, const solvers::IterationObserver& on_iteration) {
  ScopedTimer timer(times, "error estimate");
  const assembly::ScatterPlan& plan = fine.plan();
  // 1. The coarse solution on the fine mesh, its prescribed values the fine ones.
  VectorX prolonged = fem::interpolate_nodal_field(coarse.mesh(), u, dim, fine.mesh());
  for (Index dof = 0; dof < plan.n_dofs(); ++dof)
    if (plan.free_index(dof) < 0) prolonged[dof] = fine.constraints().values[dof];
  // 1b. Settle the nonlinearity on the fine mesh (a loose Newton solve from ũ): the
  // near rate-insensitive law makes the one-step linearisation miss most of the change.
  Index settle_iterations = 0;
  VectorX refined_velocity; // the settled field, kept for an adaptive run's last step
  std::unique_ptr<solvers::LinearSolver> settle_solver; // analysed there: the adjoint's too
  if (settle) {
    PhaseTimes inner;
    settle_solver = solvers::make_linear_solver(kind, solvers::MatrixStorage::SymmetricLower);
    solvers::FormingNonlinearProblem<dim> nonlinear(fine);
    const Real coarse_load = driven_load(coarse, u);
    Real previous_load = std::numeric_limits<Real>::quiet_NaN();
    int quiet_iterations = 0;
    nonlinear.set_after_iteration(
        [&](const solvers::IterationState& state) {
          solvers::AfterIteration after;
          if (!state.internal_force) return after; // a secant step: no load at hand
          const Real load = fine.driven_force(*state.internal_force) / fine.driven_height();
          const Real moved = std::abs(load - previous_load);
          quiet_iterations = moved <= settle_load_fraction * std::abs(load - coarse_load)
                                 ? quiet_iterations + 1
                                 : 0;
          previous_load = load;
          if (quiet_iterations >= 2) after.stop = solvers::StopReason::Converged;
          return after;
        },
        false);
    const solvers::SecantOutcome outcome = solvers::newton_iteration(
        nonlinear, *settle_solver, *settle, on_iteration, inner, &prolonged);
    settle_iterations = static_cast<Index>(outcome.history.size());
    VectorX settled = outcome.velocity;
    fine.discretisation().owned_dofs().replicate(settled); // ghosted on several ranks
    if (settled.allFinite()) prolonged = std::move(settled);
    refined_velocity = prolonged;
  }
  LoadErrorEstimate estimate =
      weighted_residual_estimate(coarse, u, fine, prolonged, parent, kind, settle_solver.get());
  if (!estimate.unavailable.empty()) return estimate;
  estimate.settle_iterations = static_cast<int>(settle_iterations);
  estimate.refined_velocity = std::move(refined_velocity);
  // 4. From the two-level change to the error of p_h (assumed_load_error_order); the
  // caller may observe the ratio on a third level and adds the penalties' part.
  estimate.ratio = std::pow(2.0, -assumed_load_error_order);
  estimate.discretisation_error = discretisation_tail(estimate.enriched_change, estimate.ratio);
  estimate.error = estimate.discretisation_error;
  return estimate;
}

template <int dim>
Real driven_load(const assembly::FormingProblem<dim>& problem, const VectorX& u) {
  VectorX force;
  problem.assemble_newton(u, problem.friction_thresholds(u), assembly::NewtonDuals<dim>{}, force,
                          nullptr, nullptr);
  return problem.driven_force(force) / problem.driven_height();
}

std::optional<Real> tail_ratio(std::optional<Real> observed_ratio) {
  const Real fastest = std::pow(2.0, -assumed_load_error_order);
  if (!observed_ratio) return fastest;
  if (!(*observed_ratio > 0.0 && *observed_ratio < 1.0)) return std::nullopt;
  return std::max(fastest, *observed_ratio);
}

Real discretisation_tail(Real refined_change, Real ratio) {
  FF_ASSERT(ratio >= 0.0 && ratio < 1.0, "a contracting tail");
  return grid_convergence_safety_factor * std::abs(refined_change) / (1.0 - ratio);
}

Real tail_beyond_refined(Real refined_change, Real ratio) {
  return discretisation_tail(refined_change, ratio) * ratio;
}

Real load_error_bound(Real refined_change, Real ratio, Real penalty_change) {
  return discretisation_tail(refined_change, ratio) + std::abs(penalty_change);
}

Real coarser_levels_bound(Real coarser_change, Real ratio, Real penalty_change) {
  return tail_beyond_refined(coarser_change, ratio) + std::abs(penalty_change);
}

template <int dim>
std::vector<Index> parent_cells(const mesh::Mesh<dim>& coarse, const mesh::Mesh<dim>& fine) {
  using Box = Eigen::AlignedBox<Real, dim>;
  const auto centroid = [](const mesh::Mesh<dim>& mesh, Index cell) {
    Point<dim> sum = Point<dim>::Zero();
    for (int a = 0; a < mesh.nodes_per_cell(); ++a) sum += mesh.nodes.col(mesh.cells(a, cell));
    return Point<dim>(sum / mesh.nodes_per_cell());
  };
  // Buckets of a uniform grid over the coarse mesh, about one coarse cell per bucket.
  Box all;
  std::vector<Box> boxes(coarse.n_cells());
  std::vector<Point<dim>> centres(coarse.n_cells());
  for (Index cell = 0; cell < coarse.n_cells(); ++cell) {
    for (int a = 0; a < coarse.nodes_per_cell(); ++a)
      boxes[cell].extend(Point<dim>(coarse.nodes.col(coarse.cells(a, cell))));
    all.extend(boxes[cell]);
    centres[cell] = centroid(coarse, cell);
  }
  const int per_axis = std::max(
      1, static_cast<int>(std::ceil(std::pow(static_cast<Real>(coarse.n_cells()), 1.0 / dim))));
  const Point<dim> extent = all.sizes().cwiseMax(std::numeric_limits<Real>::min());
  const auto bucket_of = [&](const Point<dim>& x, int axis) {
    const int k = static_cast<int>((x[axis] - all.min()[axis]) / extent[axis] * per_axis);
    return std::clamp(k, 0, per_axis - 1);
  };
  std::map<std::array<int, dim>, std::vector<Index>> buckets;
  for (Index cell = 0; cell < coarse.n_cells(); ++cell) {
    std::array<int, dim> low, high;
    for (int axis = 0; axis < dim; ++axis) {
      low[axis] = bucket_of(boxes[cell].min(), axis);
      high[axis] = bucket_of(boxes[cell].max(), axis);
    }
    std::array<int, dim> key = low;
    while (true) { // every bucket in [low, high]
      buckets[key].push_back(cell);
      int axis = 0;
      while (axis < dim && ++key[axis] > high[axis]) key[axis] = low[axis], ++axis;
      if (axis == dim) break;
    }
  }
  std::vector<Index> parent(fine.n_cells(), 0);
  for (Index cell = 0; cell < fine.n_cells(); ++cell) {
    const Point<dim> x = centroid(fine, cell);
    std::array<int, dim> key;
    for (int axis = 0; axis < dim; ++axis) key[axis] = bucket_of(x, axis);
    const auto found = buckets.find(key);
    if (found == buckets.end()) continue; // outside every box: not for nested meshes
    // The nearest centroid among the boxes that hold x (among all, if none does).
    const Real slack = 1e-12 * extent.maxCoeff();
    std::pair<bool, Real> best{false, std::numeric_limits<Real>::infinity()};
    for (Index candidate : found->second) {
      const std::pair<bool, Real> rank{boxes[candidate].exteriorDistance(x) <= slack,
                                       -(centres[candidate] - x).squaredNorm()};
      if (rank.first > best.first || (rank.first == best.first && -rank.second < best.second)) {
        best = {rank.first, -rank.second};
        parent[cell] = candidate;
      }
    }
  }
  return parent;
}

template LoadErrorEstimate
estimate_load_error<2>(const assembly::FormingProblem<2>&, const VectorX&,
                       const assembly::FormingProblem<2>&, const std::vector<Index>&,
                       solvers::LinearSolverKind, const solvers::IterationControl*, PhaseTimes&,
                       const solvers::IterationObserver&);
template LoadErrorEstimate
estimate_load_error<3>(const assembly::FormingProblem<3>&, const VectorX&,
                       const assembly::FormingProblem<3>&, const std::vector<Index>&,
                       solvers::LinearSolverKind, const solvers::IterationControl*, PhaseTimes&,
                       const solvers::IterationObserver&);
template LoadErrorEstimate weighted_residual_estimate<2>(
    const assembly::FormingProblem<2>&, const VectorX&, const assembly::FormingProblem<2>&,
    const VectorX&, const std::vector<Index>&, solvers::LinearSolverKind, solvers::LinearSolver*);
template LoadErrorEstimate weighted_residual_estimate<3>(
    const assembly::FormingProblem<3>&, const VectorX&, const assembly::FormingProblem<3>&,
    const VectorX&, const std::vector<Index>&, solvers::LinearSolverKind, solvers::LinearSolver*);
template Real driven_load<2>(const assembly::FormingProblem<2>&, const VectorX&);
template Real driven_load<3>(const assembly::FormingProblem<3>&, const VectorX&);
template std::vector<Index> parent_cells<2>(const mesh::Mesh<2>&, const mesh::Mesh<2>&);
template std::vector<Index> parent_cells<3>(const mesh::Mesh<3>&, const mesh::Mesh<3>&);

} // namespace formflow::post
