// SPDX-License-Identifier: MIT
// The error estimate's other levels: solved to δ by Newton or by the run's own loop, and
// the case with its regularisations doubled (app/load_error.cpp,
// app/coarser_levels_estimate.cpp and the adaptive run share them).
#pragma once

#include "formflow/app/run.hpp"
#include "formflow/app/run_plan.hpp"
#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/post/results.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace formflow::app {

/// An estimate that was not computed, and why (summary.json `unavailable`).
post::LoadErrorEstimate no_estimate(std::string why);

/// The monitor's stage of one of the estimate's solves: what it solves and on how many
/// dofs (a user waiting through a long estimate sees what is running).
template <int dim>
IterationCallback level_stage(const IterationCallback& on_iteration, std::string_view what,
                              const mesh::Mesh<dim>& mesh);

/// The mixed formulation's condensed pressure (and contact multipliers) attached to
/// `problem`; null for the penalty formulation. Owned by the caller, who keeps it alive
/// as long as `problem`.
template <int dim>
std::unique_ptr<assembly::ConstraintMultipliers<dim>>
attached_pressure_multipliers(const RunPlan& plan, const mesh::Mesh<dim>& mesh,
                              assembly::FormingProblem<dim>& problem);

/// A converged Newton solve of `plan` (to its δ) on `mesh` from `start` (a field on
/// `mesh`; its prescribed values are replaced), and the load there: the third level
/// and the doubled-penalty run of the estimate. std::nullopt if it did not converge.
/// `solution`, if given, receives the velocity (whole on every rank).
template <int dim>
std::optional<Real> solved_load(const RunPlan& plan, const mesh::Mesh<dim>& mesh, VectorX start,
                                Index& iterations, const IterationCallback& on_iteration,
                                VectorX* solution = nullptr);

/// The case's structured channel at `size` (a level of the estimate).
template <int dim> mesh::Mesh<dim> channel_at(const RunPlan& plan, Real size);

/// A level of the estimate: its mesh, load and velocity (whole on every rank).
template <int dim> struct SolvedLevel {
  mesh::Mesh<dim> mesh;
  Real load = 0.0;
  VectorX velocity;
  VectorX temperature; ///< nodal T of a hot level solved by its own stages; else empty
};

/// `mesh` solved to δ by Newton from `start` (a field on `mesh`); its load the driven
/// force (solved_load). Adds its Newton iterations to `iterations`.
template <int dim>
std::optional<SolvedLevel<dim>> solved_level(const RunPlan& plan, mesh::Mesh<dim> mesh,
                                             VectorX start, Index& iterations,
                                             const IterationCallback& on_iteration);

/// The same level solved by the run's own loop (simulate_from: exact friction's
/// augmentation, Uzawa steps, the saddle point), started from `start` where that loop
/// takes a start, its load the reported reaction. For the problems Newton does not
/// reach: their load is the secant system's driven force with the multipliers.
template <int dim>
std::optional<SolvedLevel<dim>> solved_by_own_loop(const RunPlan& plan, mesh::Mesh<dim> mesh,
                                                   const VectorX& start, Index& iterations,
                                                   const IterationCallback& on_iteration);

/// The nodal temperature `T` on `problem`'s mesh set as its flow law's temperature (at
/// the full-rule points, and at the Γ3 points for a shear-yield threshold), clamped as the
/// coupling clamps it (law_temperatures): a level of a hot run's estimate at that level's T.
template <int dim>
void set_level_temperature(const RunPlan& plan, assembly::FormingProblem<dim>& problem,
                           const VectorX& T);

/// The case with every regularisation doubled: the penalties d (incompressibility, also
/// the mixed formulation's), d_N (contact) and d_T (friction), and the paper's power
/// law's rate sensitivity α (its limit α → 0 is the rigid-plastic problem the slip-line
/// referees solve; other laws' rate dependence is the material's, not doubled).
RunPlan doubled_regularisations(const RunPlan& plan);

/// Which regularisation the load's offset |p(2ε) − p(ε)| comes from: for each key
/// doubled_regularisations doubles (penalty.d, penalty.d_n, friction.d_t with friction,
/// the power law's material.alpha), the load on `mesh` with that one doubled, solved by
/// Newton from the converged `u`, minus `load` (u's). Largest |offset| first; a solve
/// that did not converge is left out. For a message that says what to lower: the
/// offsets of one key at a time do not add up to the doubled-together offset exactly.
template <int dim>
std::vector<std::pair<std::string, Real>> regularisation_offsets(const RunPlan& plan,
                                                                 const mesh::Mesh<dim>& mesh,
                                                                 const VectorX& u, Real load);

} // namespace formflow::app
