// SPDX-License-Identifier: MIT
// The load's error estimate of a run: the refined mesh and problem it needs.
#pragma once

#include "formflow/assembly/forming_problem.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/io/case.hpp"
#include "formflow/mesh/uniform_refinement.hpp"
#include "formflow/post/results.hpp"

namespace formflow::app {

/// solver.load_error = "auto" estimates on the refined mesh (4–8 times the run's cost,
/// 2^dim times its dofs) only up to this many refined dofs: about 10 s of Newton in 2D
/// on this project's machine (the adaptive runs' settles: 184 530 dofs, 7 iterations,
/// docs/error-estimation.md) and a few GB in 3D. Above it a run whose mesh has no
/// coarser levels gets no estimate unless it asks for "refined".
inline constexpr Index auto_refined_dofs_limit = 200000;

/// solver.load_error with "auto" resolved for a run of `n_dofs` dofs on a mesh of
/// dimension `dim` (`mesh_from_case`: the case's own mesh source made it): "coarser"
/// where the case's structured channel admits 2h and 4h, else "refined" up to
/// auto_refined_dofs_limit refined dofs, else None with `why` set. Any other asked
/// method is returned as it is.
solvers::LoadErrorMethod resolved_load_error_method(const io::Case& case_, bool mesh_from_case,
                                                    int dim, Index n_dofs, std::string& why);

/// The refined mesh of the estimate and each of its cells' parent in `mesh`: the
/// structured channel at half the size when the case's structured mesh ran
/// (`mesh_from_case`), else `mesh` split uniformly.
template <int dim>
mesh::RefinedMesh<dim> estimate_mesh(const io::Case& case_, const mesh::Mesh<dim>& mesh,
                                     bool mesh_from_case);

/// post::estimate_load_error for `case_` solved on `problem` with velocity `u`:
/// makes the mesh refined once (case_.mesh with half the size; the structured
/// channel and its refinement by 2 nest), the same discrete problem on it (the
/// mixed formulation's condensed pressure included), and the parent of each
/// fine cell. Says why not (LoadErrorEstimate::unavailable) when solver.load_error
/// = "none", the mesh came from a file or not from the case, the run did not
/// converge, or the problem has no Newton tangent (exact friction, d = 0 or
/// d_N = 0, Taylor–Hood). The estimate is completed into a bound (post::load_error_bound):
/// a solve with the penalties doubled on the same mesh and, when the structured
/// channel admits 2h, a solve there for the observed ratio (docs/error-estimation.md).
template <int dim>
post::LoadErrorEstimate
load_error_of(const io::Case& case_, const assembly::FormingProblem<dim>& problem, const VectorX& u,
              bool mesh_from_case, bool converged, PhaseTimes& times);

/// load_error_of for a converged solution `u` of `case_` on `mesh`, the problem built
/// again (an adaptive run asks the full estimate of a cycle that ran with the cheap one).
template <int dim>
post::LoadErrorEstimate load_error_on(const io::Case& case_, const mesh::Mesh<dim>& mesh,
                                      const VectorX& u, bool mesh_from_case, PhaseTimes& times);

} // namespace formflow::app
