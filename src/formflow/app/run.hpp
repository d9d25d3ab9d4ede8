// SPDX-License-Identifier: MIT
// A run of a plan: the mesh, the stages composed around its solve, the results.
#pragma once

#include "formflow/app/run_plan.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/mesh/any_mesh.hpp"
#include "formflow/post/error_norms.hpp"
#include "formflow/post/results.hpp"
#include "formflow/post/temperature_error_norms.hpp"

#include <functional>
#include <optional>
#include <string>

namespace formflow::app {

/// Called once per nonlinear iteration with its record (for the monitor).
using IterationCallback = std::function<void(const solvers::IterationRecord&)>;

/// `on_iteration` with every record's `stage` set to `stage`, for a solve that is not
/// the run's own (an error estimate's level, an adaptive cycle), after the stage a
/// nested with_stage set ("adapt cycle 3, 2938 dofs · error estimate: ..."); empty if
/// `on_iteration` is. The records reach the caller's callback, so a stop signal is
/// honoured during those solves too.
IterationCallback with_stage(const IterationCallback& on_iteration, std::string stage);

/// One run's mesh and what was computed on it, of either dimension.
///
/// Why a variant of meshes and not a Simulation<dim>: everything a run
/// produces except the mesh is already dimension-free data (post::Results holds
/// flat node-major fields of dim components and contact samples with three
/// coordinates), so only the mesh varies. One Simulation type lets the CLI, the
/// studies and the tests hold a run without being templated themselves; the
/// code that needs dim (the solve, post-processing, the VTU writer) is
/// templated and reached by one std::visit on `mesh`, the dimension the mesh
/// source produced. The solve itself is simulate_on<dim>.
struct Simulation {
  mesh::AnyMesh mesh;
  post::Results results;
  /// Error against the exact field: only for a manufactured solution (verification.solution).
  std::optional<post::ErrorNorms> errors;
  /// Temperature error: only for the coupled manufactured solution (thermal.enabled too).
  std::optional<post::TemperatureErrorNorms> temperature_errors;
  /// CHOLMOD rcond of K(u) at the final velocity, when asked for.
  std::optional<Real> reciprocal_condition;

  int dimension() const { return mesh::dimension_of(mesh); }
  /// The mesh of a plane run, for the 2D-only consumers (pictures, the die
  /// corner of a study). Precondition: dimension() == 2 (std::bad_variant_access).
  const mesh::Mesh<2>& plane_mesh() const { return std::get<mesh::Mesh<2>>(mesh); }
};

/// Runs `plan`: its mesh (plan.make_mesh, or the unit box of a manufactured solution),
/// then the stages the plan composes around the solve (app/stages/composition.cpp), in
/// the dimension of that mesh. Throws InputError (exit 2) for a composition the stage
/// table refuses. Never throws for numerical trouble: a run that does not converge
/// returns results with the stop reason set.
Simulation simulate(const RunPlan& plan, const IterationCallback& on_iteration = {},
                    bool estimate_condition = false);

/// The forming problem of `plan` on `mesh`: everything simulate does after making the
/// mesh. The mesh's labels carry the process (the driven end, symmetry, Γ3); plan.mesh
/// is read only for mesh sequencing (solver.coarse_levels), which re-makes coarser
/// meshes from it and so applies only when `mesh` came from it: not here.
template <int dim>
Simulation simulate_on(const RunPlan& plan, mesh::Mesh<dim> mesh,
                       const IterationCallback& on_iteration = {}, bool estimate_condition = false);

/// simulate_on with Newton started from `start` (a full dof vector on `mesh`, e.g.
/// the previous adaptive cycle's solution interpolated; its prescribed values are
/// replaced by the problem's) instead of a coarse start. The load's error estimate,
/// if asked for, is computed on `mesh` refined uniformly (mesh/uniform_refinement.hpp).
template <int dim>
Simulation simulate_from(const RunPlan& plan, mesh::Mesh<dim> mesh, const VectorX& start,
                         const IterationCallback& on_iteration = {});

/// CHOLMOD rcond of the secant matrix K(u) of `problem` at velocity `u`.
template <int dim>
Real condition_at(const assembly::FormingProblem<dim>& problem, const VectorX& u);

} // namespace formflow::app
