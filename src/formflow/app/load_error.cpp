// SPDX-License-Identifier: MIT
// The refined mesh and problem of the load's error estimate.
#include "formflow/app/load_error.hpp"

#include "formflow/app/simulation.hpp"
#include "formflow/app/solve_plan.hpp"
#include "formflow/io/mesh_input.hpp"
#include "formflow/mesh/uniform_refinement.hpp"
#include "formflow/post/load_error_estimate.hpp"

#include <algorithm>
#include <memory>

namespace formflow::app {

namespace {

/// The refined mesh's Newton solve stops at this relative change (or δ if larger).
/// Measured (docs/error-estimation.md): on the sticking-ram benchmark (α = 1e-4,
/// d = 1e-4, h = 1 and 0.5) 1e-2 and 1e-3 give the same estimate to 0.5 %, but on
/// Hill's wedge drawing (15°, 30°; h = 1/4, 1/8) 1e-2 stops after 2–3 iterations
/// and misses 5–15 % of the change that 1e-3 (4–7 iterations) finds; 1e-1 (one
/// iteration) has the wrong sign.
constexpr Real settle_tolerance = 1e-3;

post::LoadErrorEstimate unavailable(std::string why) {
  post::LoadErrorEstimate estimate;
  estimate.unavailable = std::move(why);
  return estimate;
}

} // namespace

template <int dim>
post::LoadErrorEstimate
load_error_of(const io::Case& case_, const assembly::FormingProblem<dim>& problem, const VectorX& u,
              bool mesh_from_case, bool converged, PhaseTimes& times) {
  if (case_.solver.load_error == solvers::LoadErrorMethod::None)
    return unavailable("solver.load_error = \"none\"");
  if (!converged) return unavailable("the run did not converge");
  if (problem.has_exact_friction())
    return unavailable("exact friction has no Newton tangent without its multipliers");
  const bool mixed = case_.formulation.type == assembly::FormulationType::Mixed;
  if ((mixed && case_.penalty.d == 0) || case_.penalty.d_n == 0)
    return unavailable("exact constraints (d = 0 or dN = 0) have no Newton tangent");
  if (!problem.terms().newton_ready()) return unavailable("this formulation has no Newton tangent");
  mesh::Mesh<dim> fine_mesh;
  std::unique_ptr<assembly::FormingProblem<dim>> fine;
  std::unique_ptr<assembly::ConstraintMultipliers<dim>> fine_pressure;
  std::vector<Index> parent;
  {
    ScopedTimer timer(times, "error estimate");
    if (mesh_from_case && case_.mesh.source == mesh::MeshSource::Structured) {
      // The structured channel at half the size: nested in the one that ran.
      mesh::MeshSpec spec = case_.mesh;
      spec.size = case_.mesh.size / 2;
      fine_mesh = std::get<mesh::Mesh<dim>>(io::load_mesh(case_, spec));
      parent = post::parent_cells(problem.mesh(), fine_mesh);
    } else {
      // Any other mesh (Gmsh, a file, an adaptive cycle's): every cell split in 2^dim,
      // nested by construction (a Gmsh remesh at half the size would not be).
      mesh::RefinedMesh<dim> refined = mesh::refine_uniformly(problem.mesh());
      fine_mesh = std::move(refined.mesh);
      parent = std::move(refined.parent);
    }
    fine = std::make_unique<assembly::FormingProblem<dim>>(fine_mesh, problem_settings(case_));
    if (mixed) { // the condensed pressure, as on the mesh that ran (d > 0 here)
      fine_pressure = std::make_unique<assembly::ConstraintMultipliers<dim>>(
          fine_mesh, case_.penalty, case_.formulation, fine->full_rule(), fine->n_contact_points());
      fine->attach_multipliers(fine_pressure.get());
    }
    if (!fine->terms().newton_ready())
      return unavailable("the refined problem has no Newton tangent");
  }
  solvers::IterationControl settle = case_.solver;
  settle.coarse_levels = 0;
  settle.tolerance = std::max(case_.solver.tolerance, settle_tolerance);
  const bool do_settle = case_.solver.load_error == solvers::LoadErrorMethod::Refined;
  return post::estimate_load_error(problem, u, *fine, parent, make_solve_plan(case_).linear,
                                   do_settle ? &settle : nullptr, times);
}

template post::LoadErrorEstimate load_error_of<2>(const io::Case&,
                                                  const assembly::FormingProblem<2>&,
                                                  const VectorX&, bool, bool, PhaseTimes&);
template post::LoadErrorEstimate load_error_of<3>(const io::Case&,
                                                  const assembly::FormingProblem<3>&,
                                                  const VectorX&, bool, bool, PhaseTimes&);

} // namespace formflow::app
