// SPDX-License-Identifier: MIT
// The load's error estimate of a run: the refined mesh and problem it needs.
#pragma once

#include "formflow/app/run.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/mesh/uniform_refinement.hpp"
#include "formflow/post/results.hpp"

#include <string>
#include <utility>
#include <vector>

namespace formflow::app {

/// solver.load_error = "auto" estimates on the refined mesh (2^dim times the run's
/// dofs) only up to this many refined dofs. In 2D 200 000: about 10 s of Newton on
/// this project's machine (the adaptive runs' settles: 184 530 dofs, 7 iterations,
/// docs/error-estimation.md). In 3D 25 000: a hexahedral factor fills far more, and
/// the 3D examples' refined estimates took 5 s at 22 000 refined dofs (ten times their
/// run) and 20 s at 44 000. Above them a run whose mesh has no coarser levels gets no estimate
/// unless it asks for "refined".
constexpr Index auto_refined_dofs_limit(int dim) {
  return dim == 3 ? 25000 : 200000;
}

/// solver.load_error with "auto" resolved for a run of `n_dofs` dofs on a mesh of
/// dimension `dim` (`mesh_from_plan`: the case's own mesh source made it): "coarser"
/// where the case's structured channel admits 2h and 4h, else "refined" up to
/// auto_refined_dofs_limit(dim) refined dofs, else None with `why` set. Any other asked
/// method is returned as it is.
solvers::LoadErrorMethod resolved_load_error_method(const RunPlan& plan, bool mesh_from_plan,
                                                    int dim, Index n_dofs, std::string& why);

/// The refined mesh of the estimate and each of its cells' parent in `mesh`: the
/// structured channel at half the size when the case's structured mesh ran
/// (`mesh_from_plan`), else `mesh` split uniformly.
template <int dim>
mesh::RefinedMesh<dim> estimate_mesh(const RunPlan& plan, const mesh::Mesh<dim>& mesh,
                                     bool mesh_from_plan);

/// The load's error estimate of a run of `plan` on `problem` with velocity `u` and
/// reported load `run_load`, by solver.load_error (resolved_load_error_method):
/// - "refined" / "linearized": post::estimate_load_error on the mesh refined once
///   (plan.mesh at half the size when the case's structured channel ran, which nests;
///   else every cell split), the same discrete problem there (the mixed formulation's
///   condensed pressure included), completed into a bound (post::load_error_bound) by a
///   solve with the regularisations doubled on the same mesh and a third level for the
///   observed ratio (2h where the channel admits it, else h/4). Needs Newton's tangent:
///   unavailable for exact friction, d = 0 or d_N = 0, Taylor–Hood.
/// - "coarser": the loads at 2h and 4h (post::coarser_levels_bound), by Newton where it
///   reaches the problem, else by the run's own loop on each level.
/// - a hot run, "refined" or "coarser" asked for: every level a whole hot run of the
///   stages (the coupling around the loop, solved_by_own_loop); see hot_refined_estimate.
/// Says why not (LoadErrorEstimate::unavailable) for "none", a run that did not
/// converge, a hot run under "auto" or "linearized", or a mesh the method cannot use
/// (docs/error-estimation.md).
template <int dim>
post::LoadErrorEstimate
load_error_of(const RunPlan& plan, const assembly::FormingProblem<dim>& problem, const VectorX& u,
              Real run_load, bool mesh_from_plan, bool converged, PhaseTimes& times,
              const IterationCallback& on_iteration = {});

/// load_error_of for a converged solution `u` of `plan` on `mesh`, the problem built
/// again (an adaptive run asks the full estimate of a cycle that ran with the cheap one).
template <int dim>
post::LoadErrorEstimate load_error_on(const RunPlan& plan, const mesh::Mesh<dim>& mesh,
                                      const VectorX& u, bool mesh_from_plan, PhaseTimes& times,
                                      const IterationCallback& on_iteration = {});

} // namespace formflow::app
