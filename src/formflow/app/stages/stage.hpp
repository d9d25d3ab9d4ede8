// SPDX-License-Identifier: MIT
// The outer loops' one interface: a stage runs the stages inside it on a solve's state
// (issue 43; docs/architecture.md "Stages").
#pragma once

#include "formflow/app/run.hpp"
#include "formflow/assembly/constraint_multipliers.hpp"
#include "formflow/assembly/friction_multipliers.hpp"
#include "formflow/core/error.hpp"
#include "formflow/solvers/linear_solver.hpp"
#include "formflow/solvers/secant_iteration.hpp"
#include "formflow/solvers/stop_reason.hpp"

#include <memory>
#include <span>
#include <string_view>

namespace formflow::app {

/// One solve on one mesh as the stages hand it inwards and back: what the outer stages
/// set (the plan as this solve sees it, a start, the loop's control), what the solve
/// stage builds (the problem) and what the loop leaves (its outcome and multipliers).
/// A stage that runs its inner stages several times (the coupling steps, the adaptive
/// cycles) changes what it owns between the runs and reads the outcome after each.
template <int dim> struct SolveState {
  const RunPlan* plan = nullptr;    ///< never null
  Simulation* simulation = nullptr; ///< its mesh (a Mesh<dim>) and results; never null
  /// The mesh is plan->mesh's own (so its coarser and finer levels can be re-made).
  bool mesh_from_plan = true;
  /// The loop's first iterate (a full dof vector on the mesh), or its own start.
  const VectorX* start = nullptr;
  IterationCallback on_iteration;
  bool estimate_condition = false; ///< CHOLMOD's rcond of K(u) after the solve
  /// The loop's iteration control: plan->solver, its δ lowered per coupling step.
  solvers::IterationControl control;

  // Set by the solve stage for the stages inside it, kept for the ones outside it.
  std::unique_ptr<assembly::FormingProblem<dim>> problem;
  std::unique_ptr<assembly::ConstraintMultipliers<dim>> constraint_multipliers;
  /// The linear solver of the loop, when a stage keeps one over several loops (the
  /// coupling steps: one symbolic analysis); null: each loop makes the plan's.
  std::shared_ptr<solvers::LinearSolver> solver;

  // Left by the loop.
  solvers::SecantOutcome outcome;
  assembly::FrictionMultipliers<dim> multipliers;

  const RunPlan& run_plan() const { return *plan; }
  const mesh::Mesh<dim>& mesh() const { return std::get<mesh::Mesh<dim>>(simulation->mesh); }
  post::Results& results() const { return simulation->results; }
};

class StageChain;

/// An outer loop around a solve, or the solve itself. A stage owns its stop rule, its
/// records to the monitor (IterationRecord::stage or its own records) and its block in
/// summary.json (a member of post::Results); it reaches the solve only through
/// `inner`, the stages composed inside it (app/stages/composition.cpp).
class Stage {
public:
  virtual ~Stage() = default;
  /// Its name in the docs and in errors about the composition ("thermal coupling").
  virtual std::string_view name() const = 0;
  virtual void run(SolveState<2>& state, const StageChain& inner) const = 0;
  virtual void run(SolveState<3>& state, const StageChain& inner) const = 0;
};

/// The stages inside a stage, outermost first: run() runs the first with the others
/// as its inner chain. An empty chain is a bug (the loop stage ends every chain).
class StageChain {
public:
  explicit StageChain(std::span<const Stage* const> stages) : stages_(stages) {}
  template <int dim> void run(SolveState<dim>& state) const {
    FF_ASSERT(!stages_.empty(), "the composition ends every chain with a solve");
    stages_.front()->run(state, StageChain(stages_.subspan(1)));
  }
  bool empty() const { return stages_.empty(); }

private:
  std::span<const Stage* const> stages_;
};

/// A stage written once for both dimensions: `Derived` has
/// `template <int dim> void run_on(SolveState<dim>&, const StageChain&) const`,
/// defined in its own file (which is where both overrides are instantiated).
template <class Derived> class StageOf : public Stage {
public:
  void run(SolveState<2>& state, const StageChain& inner) const override {
    static_cast<const Derived&>(*this).template run_on<2>(state, inner);
  }
  void run(SolveState<3>& state, const StageChain& inner) const override {
    static_cast<const Derived&>(*this).template run_on<3>(state, inner);
  }
};

/// The stages formflow has, each in its own file of app/stages/ (one registration each
/// in composition.cpp).
const Stage& adapt_stage();        ///< adaptive cycles: solve, estimate, mark, remesh
const Stage& estimate_stage();     ///< the load's error bar after the solve
const Stage& manufactured_stage(); ///< a manufactured solution on the unit box
const Stage& solve_stage();        ///< the problem on the mesh, the results after the loop
const Stage& thermal_stage();      ///< heat ↔ flow until neither changes
const Stage& coarse_start_stage(); ///< the loop's start from coarser meshes
const Stage& loop_stage();         ///< the plan's nonlinear loop

} // namespace formflow::app
