// SPDX-License-Identifier: MIT
// Mesh sequencing: Newton's first iterate from the solution on coarser meshes.
#pragma once

#include "formflow/app/run_plan.hpp"
#include "formflow/assembly/discretisation.hpp"
#include "formflow/core/timer.hpp"
#include "formflow/mesh/mesh.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <optional>
#include <vector>

namespace formflow::app {

/// The coarse levels' work, reported beside the fine mesh's own iterations.
struct CoarseStart {
  VectorX velocity;             ///< the coarse solution at the fine mesh's nodes
  std::vector<Real> mesh_sizes; ///< coarsest first
  std::vector<int> iterations;  ///< iterations per coarse level (Newton's, or the saddle
                                ///< point's secant steps), coarsest first
  bool converged = true;        ///< every coarse level reached δ
};

/// Whether the structured mesh of `spec` (plane or solid) can be made at `size`:
/// every length the generator divides is a multiple of it and the exit keeps fewer
/// cells than the entry (the levels of mesh sequencing and of the load's estimate).
bool size_fits(const mesh::MeshSpec& spec, Real size);

/// Nested iteration (solver.coarse_levels = L > 0): solves `plan` with Newton on
/// the meshes of size 2^L h, ..., 2h (h = mesh.size; a structured channel mesh and
/// its refinement by 2 nest exactly), the coarsest from the constant-viscosity
/// solution and each finer one from the previous solution interpolated to its
/// nodes (fem/nodal_interpolation.hpp), and returns the last one interpolated to
/// `fine`. Why: Newton's count from the constant-viscosity start grows with
/// refinement (the plastic zones settle over 5–6 damped steps, docs/benchmarks.md);
/// from a 2h solution the plastic zones are nearly in place (measured: 6 fine
/// iterations at 77 762 dofs for L = 2, against 11–14).
/// The secant loop of a discontinuous pressure kept as a saddle point (the iterative
/// PETSc path) is sequenced too: with d > 0 and d_N > 0 its levels solve the same
/// problem with the pressure condensed, by Newton on CHOLMOD (6–9 steps of a small
/// factorisation against 18–136 secant steps of Krylov solves); with d = 0 or d_N = 0
/// by the saddle point's own secant loop and solver.
/// Each coarse level stops at max(δ, 1e-2) (finer is wasted: the levels' solutions
/// differ by more). Only the levels whose mesh the geometry admits are used
/// (2^L h must divide its lengths; mesh II, h = 1, has none). All phases are timed into `times`
/// (the coarse solves in the solver's own phases, meshing, set-up and
/// interpolation as "coarse start"), so the solver time includes the coarse work.
/// std::nullopt when no coarse level is used (L = 0, none fits, mesh from a file).
/// Each level varies only the mesh spec (plan.mesh with a larger size) and the
/// iteration control; the plan itself is read, never copied. `fine` is the run's
/// discretisation, of the dimension the case's mesh source makes, and so is every
/// coarse level. Each level's velocity goes to the next mesh by interpolation, its Γ3
/// nodes' normal velocity (which carries the contact pressure) as a scalar of its own
/// (assembly::set_contact_normal_velocity).
template <int dim>
std::optional<CoarseStart>
coarse_start(const RunPlan& plan, const assembly::Discretisation<dim>& fine, PhaseTimes& times);

} // namespace formflow::app
