// SPDX-License-Identifier: MIT
// The outer loops' composition table: each row a pair that does not compose yet.
#include "formflow/solvers/stage_table.hpp"

#include <fmt/format.h>

#include <functional>
#include <vector>

namespace formflow::solvers {

namespace {

using StageRow = std::function<std::optional<StageRefusal>(const StageSet&)>;

/// A refusal of the adaptive cycles (the run without them: adapt.target_error = 0).
StageRefusal adapt_refusal(std::string key, std::string message, std::string hint = {}) {
  const std::string off = "set adapt.target_error = 0 (no adaptivity)";
  return {std::move(key), "adapt.target_error", std::move(message),
          hint.empty() ? off : off + ", or " + hint};
}

/// A refusal of the distributed run (the run without it: one process).
StageRefusal distributed_refusal(const StageSet& stages, std::string key, std::string_view what,
                                 std::string hint) {
  return {std::move(key), "mpi ranks",
          fmt::format("on {} MPI ranks: a distributed run (docs/petsc.md) {}", stages.ranks, what),
          std::move(hint)};
}

/// The table, in the order its rows are checked. The adaptive cycles need the load's
/// error estimate with Newton's tangent (docs/error-estimation.md) on a forming load;
/// the distributed run needs what each rank can hold a share of (docs/petsc.md).
const std::vector<StageRow>& stage_rows() {
  static const std::vector<StageRow> rows = {
      [](const StageSet& s) -> std::optional<StageRefusal> {
        if (!s.adapt || !s.manufactured) return std::nullopt;
        return adapt_refusal("verification.solution",
                             "adaptivity estimates a forming load, which a "
                             "manufactured solution does not have");
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        if (!s.adapt || !s.exact_friction) return std::nullopt;
        return adapt_refusal("friction.regularization",
                             "exact friction has no error estimate to drive adaptivity (no "
                             "Newton tangent without its multipliers)",
                             "a regularised friction law (friction.regularization)");
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        if (!s.adapt || !(s.exact_incompressibility || s.exact_contact)) return std::nullopt;
        return adapt_refusal(s.exact_contact ? "penalty.dN" : "penalty.d",
                             "exact constraints (d = 0 or dN = 0) have no error estimate to "
                             "drive adaptivity",
                             "a penalty > 0");
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        if (!s.adapt || s.newton) return std::nullopt;
        return adapt_refusal("solver.method",
                             "adaptivity restarts each cycle's Newton from the previous "
                             "solution; the secant iteration has no such start",
                             "solver.method = \"newton\"");
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        // The linearised estimate is one adjoint at u prolonged, no settle: a hot level
        // is a whole hot run (the coupling around the loop), which "refined" and
        // "coarser" solve.
        if (!s.thermal || !s.linearized_estimate_asked) return std::nullopt;
        return StageRefusal{"solver.load_error", "thermal.enabled",
                            "hot forming has no linearised load error estimate: each level of "
                            "a hot run's estimate is a whole hot run, which the linearised one "
                            "does not solve",
                            "set solver.load_error = \"refined\" or \"coarser\" (their levels "
                            "solve the coupling), \"auto\" or \"none\", or thermal.enabled = "
                            "false"};
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        if (s.ranks <= 1 || s.petsc) return std::nullopt;
        return distributed_refusal(s, "solver.linear", "needs the PETSc back-end",
                                   "set solver.linear = \"petsc\", or run as one process");
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        if (s.ranks <= 1 || !s.manufactured) return std::nullopt;
        return distributed_refusal(s, "verification.solution", "solves forming cases only",
                                   "run it as one process");
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        // Exact friction's multipliers are updated per Γ3 point from the replicated
        // velocity, alike on every rank; its exact stick condenses T, which a rank holds
        // a share of.
        if (s.ranks <= 1 || !s.exact_stick) return std::nullopt;
        return distributed_refusal(s, "friction.stick",
                                   "imposes no exact stick yet (it condenses the whole tangent)",
                                   "set friction.stick = \"augmented\", or run as one process");
      },
      [](const StageSet& s) -> std::optional<StageRefusal> {
        // A discontinuous pressure kept as a saddle point runs distributed: each pressure
        // dof is one cell's, so one rank's (assembly/saddle_point_system.hpp).
        if (s.ranks <= 1 || !s.taylor_hood_saddle_point) return std::nullopt;
        return distributed_refusal(
            s, "formulation.pressure", "has no Taylor–Hood saddle point yet",
            "set formulation.pressure = \"P1disc\" or \"P0\" (with "
            "formulation.discontinuous_pressure = \"saddle_point\" for the iterative path), "
            "or run as one process");
      },
  };
  return rows;
}

} // namespace

std::optional<StageRefusal> refused_composition(const StageSet& stages) {
  for (const StageRow& row : stage_rows())
    if (std::optional<StageRefusal> refusal = row(stages)) return refusal;
  return std::nullopt;
}

} // namespace formflow::solvers
