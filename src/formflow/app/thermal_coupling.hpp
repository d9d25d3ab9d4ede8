// SPDX-License-Identifier: MIT
// Hot forming: the staggered loop between the flow and the heat problem (issue 18).
#pragma once

#include "formflow/app/run.hpp"
#include "formflow/assembly/forming_problem.hpp"
#include "formflow/assembly/heat_problem.hpp"
#include "formflow/post/results.hpp"
#include "formflow/solvers/secant_iteration.hpp"

#include <functional>

namespace formflow::app {

/// The plan's nonlinear loop on the problem as it stands (its point temperatures set),
/// from `start` (null: the loop's own start), to the relative change `tolerance`.
using FlowSolve = std::function<solvers::SecantOutcome(const VectorX* start, Real tolerance)>;

/// The heat sources at the velocity `u`: β σ_p ε̄̇ at the full-rule points and the
/// friction share of λ_T·u_T at the Γ3 points (the friction power's own integrand).
template <int dim>
assembly::HeatSources heat_sources(const assembly::FormingProblem<dim>& problem,
                                   const physics::Thermal& thermal, const VectorX& u,
                                   const assembly::FrictionMultipliers<dim>* multipliers);

/// The flow law's temperature at the points: T clamped to [lowest prescribed T,
/// thermal.max_temperature], the range condition (2.11) was checked on.
std::vector<Real> law_temperatures(const physics::Thermal& thermal, std::vector<Real> T);

/// What a coupled manufactured solution changes in the heat problem: the exact T on all
/// of ∂Ω instead of the billet's on Γ1, and a heat source added to β σ_p ε̄̇.
template <int dim> struct ManufacturedHeat {
  typename assembly::HeatProblem<dim>::BoundaryTemperature temperature;
  std::vector<Real> source; ///< at every full-rule point, cell-major
};

/// Staggered coupling: flow at the billet temperature, then heat ↔ flow until the
/// temperature (relative to its rise) and the process pressure change by less than
/// thermal.coupling_tolerance, with each flow solved to max(δ, min(1e-2, ΔT/10)) for the
/// relative change ΔT of the heat solve before it (inexact staggering) and the last one
/// to δ = `final_tolerance` (solver.tolerance); `friction` says whether the Γ3 points
/// need their T (a shear-yield threshold); the last step is a heat solve, not a flow solve at a T
/// the flow already has (within the tolerance). Each step's closing record goes to `on_iteration`
/// (IterationRecord::coupling > 0); fills results.thermal and returns the last flow
/// outcome, whose stop reason is CouplingLimit when the coupling did not converge.
template <int dim>
solvers::SecantOutcome
couple_thermal(const physics::Thermal& thermal, const physics::Friction& friction,
               Real final_tolerance, assembly::FormingProblem<dim>& problem,
               const FlowSolve& solve_flow, const IterationCallback& on_iteration,
               const assembly::FrictionMultipliers<dim>& multipliers, post::Results& results,
               const ManufacturedHeat<dim>* manufactured = nullptr);

} // namespace formflow::app
