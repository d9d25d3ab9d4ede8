// SPDX-License-Identifier: MIT
// A goal-oriented (dual-weighted residual) estimate of the load's discretisation
// error: the adjoint of the reaction functional on the mesh refined once.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/post/results.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/linear_solver_kind.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <functional>
#include <optional>
#include <string>

namespace formflow::post {

/// The asymptotic order r of the load error |p_h − p| ≈ C h^r assumed to turn the
/// two-level change p_{h/2} − p_h into an estimate of p_h − p: under
/// |p − p_{h/2}| = 2^{-r} |p − p_h|, |p − p_h| = |p_{h/2} − p_h| / (1 − 2^{-r}).
/// r = 1 is the order the die corner's velocity discontinuity (the slip-line
/// fields' centred fans) allows, observed for the square and the wedge dies
/// (docs/validation.md, docs/error-estimation.md); a faster-converging load makes
/// the estimate pessimistic by at most 2 (1 − 2^{-r}) < 2, a slower one optimistic.
inline constexpr Real assumed_load_error_order = 1.0;

/// The ratio q of successive load differences (p_{h/4} − p_{h/2}) / (p_{h/2} − p_h)
/// taken for the tail p − p_{h/2} = (p_{h/2} − p_h)(q + q² + …) of the geometric
/// series: the larger of 2^{-r} (r = assumed_load_error_order, the fastest the
/// die corner allows) and the ratio observed on the three levels 2h, h, h/2, so that
/// a load converging more slowly than first order on these levels is not
/// extrapolated at first order. std::nullopt when the observed ratio is not in
/// (0, 1): the levels do not contract monotonically (pre-asymptotic), and no tail
/// can be summed.
std::optional<Real> tail_ratio(std::optional<Real> observed_ratio);

/// The safety factor F_s on the discretisation part: Roache's grid convergence
/// index factor for a study on three grids with an observed order. The tail ratio q
/// is observed on the levels 2h, h, h/2, and on the wedges' pre-asymptotic levels
/// the ratios that follow it are larger (0.527 and 0.545 needed against 0.517 and
/// 0.536 observed at h = 1/4: docs/error-estimation.md, step 5 (iv)). F_s covers a
/// mean tail ratio up to 1 − (1 − q)/F_s (0.6 for q = ½); its cost is a 25 % wider
/// error bar.
inline constexpr Real grid_convergence_safety_factor = 1.25;

/// The discretisation part of the estimate of |p_h − p|: the whole geometric tail
/// from p_h, F_s |p_{h/2} − p_h| / (1 − q).
Real discretisation_tail(Real refined_change, Real ratio);

/// The same tail beyond p_{h/2} (the refined mesh's own discretisation error):
/// F_s |p_{h/2} − p_h| q / (1 − q).
Real tail_beyond_refined(Real refined_change, Real ratio);

/// The estimate of |p_h − p| from the loads on coarser levels (solver.load_error =
/// "coarser"): the tail beyond p_h of the geometric series whose last difference is
/// p_h − p_{2h}, F_s |p_h − p_{2h}| q / (1 − q) (tail_beyond_refined with h in the
/// role of the refined level), plus |penalty_change|, in magnitude. No solve finer
/// than the run's: the difference is one level coarser than the refined estimate's,
/// so q is observed on 4h, 2h, h (docs/error-estimation.md, "The cheap default").
Real coarser_levels_bound(Real coarser_change, Real ratio, Real penalty_change);

/// The estimate of |p_h − p|: discretisation_tail (the discretisation error) plus
/// |p_h(2ε) − p_h(ε)| (the penalties' first-order offset p(ε) − p(0), estimated on
/// the same mesh). Both added in magnitude: their signs are not assumed to cancel.
Real load_error_bound(Real refined_change, Real ratio, Real penalty_change);

/// The DWR estimate for the driven-end reaction Q(u) = Σ_driven f_i(u) (the ram
/// reaction, the drawing force). `fine` is the same discrete problem on the mesh
/// refined once (nested in `coarse`'s); `u` the solution on `coarse`.
///  1. ũ = u prolonged to the fine mesh (exact: the spaces nest); with `settle`,
///     Newton from there to settle's δ or until two successive iterations each move
///     the load by at most 1 % of its change from p_h, whichever comes first.
///  2. The adjoint z on the fine mesh: Jᵀ z = ∂Q/∂u_free with J the Newton tangent
///     at ũ (primal, the exact Jacobian; τ_f frozen), i.e. (T + Nᵀ) z = g; T is
///     factorised once, Nᵀ (the full-ε̇ form's unsymmetric rest and a pressure-
///     dependent threshold's dτ_f) goes into GMRES preconditioned by T. With the
///     mixed formulation's multipliers the friction part has no transpose: unavailable.
///  3. W = (1 on the driven dofs, −z on the free ones): Q(ũ) − z·R(ũ) = W·f(ũ) is
///     Q on the fine mesh after one linearised step, W_h = W at the coarse nodes is
///     a lifting for the coarse reaction, and per coarse cell K
///     η_K = Σ_{children k} W_k·f_k(ũ) − W_h,K·f_K(u) (Galerkin orthogonality on
///     the coarse space is what the subtraction removes).
///  4. discretisation_error = F_s |Σ η_K| / (1 − 2^{-r}) / height, r =
///     assumed_load_error_order (the caller may replace the ratio from a third
///     level and add the penalties' part: app/load_error.cpp).
/// `parent` maps each fine cell to its coarse cell. Timed as "error estimate". The
/// settle's iterations go to `on_iteration` (a monitor; a stop signal's check).
template <int dim>
LoadErrorEstimate
estimate_load_error(const assembly::FormingProblem<dim>& coarse, const VectorX& u,
                    const assembly::FormingProblem<dim>& fine, const std::vector<Index>& parent,
                    solvers::LinearSolverKind kind, const solvers::IterationControl* settle,
                    PhaseTimes& times,
                    const std::function<void(const solvers::IterationRecord&)>& on_iteration = {});

/// Steps 2 and 3 of estimate_load_error at a given fine field `fine_velocity` (whole
/// on every rank; the settled ũ there): the adjoint at it, the weights and the cell
/// indicators of `coarse` (each fine cell's share to its `parent`), their sum in
/// enriched_change. With both fields converged solutions the sum is the solved
/// difference p_fine − p_coarse (the residuals vanish to δ), so the "coarser" estimate
/// gets its cell indicators from the run's mesh over 2h (app/coarser_levels_estimate.cpp).
/// `error` is left unset; `unavailable` says why when no adjoint could be solved.
/// `analysed`: a solver of `kind` whose analysis is of fine's pattern (the settle's), used
/// for the adjoint instead of a new one (its ordering is not computed again); null: new.
template <int dim>
LoadErrorEstimate
weighted_residual_estimate(const assembly::FormingProblem<dim>& coarse, const VectorX& u,
                           const assembly::FormingProblem<dim>& fine, const VectorX& fine_velocity,
                           const std::vector<Index>& parent, solvers::LinearSolverKind kind,
                           solvers::LinearSolver* analysed = nullptr);

/// The load Q(u)/height of `problem` at `u`: the driven rows of the Newton assembly's
/// internal force, as the estimate's weighted residuals count it.
template <int dim> Real driven_load(const assembly::FormingProblem<dim>& problem, const VectorX& u);

/// For each cell of `fine`, the cell of `coarse` that contains its centroid (the
/// mean of its nodes): bounding-box buckets, then the nearest centroid among the
/// cells whose box holds it. Exact for a mesh and its refinement by 2 with
/// cells that are not too skewed (a child's centroid lies at the parent's
/// reference point (±½, ±½)).
template <int dim>
std::vector<Index> parent_cells(const mesh::Mesh<dim>& coarse, const mesh::Mesh<dim>& fine);

} // namespace formflow::post
