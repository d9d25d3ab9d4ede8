// SPDX-License-Identifier: MIT
// The capability table of the nonlinear loops.
#include "formflow/solvers/capabilities.hpp"

#include "formflow/solvers/linear_solver.hpp"

#include <fmt/format.h>

#include <optional>

namespace formflow::solvers {

namespace {

/// The key that made the problem a saddle point.
std::string_view pressure_key(const ProblemShape& shape) {
  return shape.discontinuous_saddle_point ? "formulation.discontinuous_pressure"
                                          : "formulation.pressure";
}

/// The combinations that no loop serves yet, each with its reason.
std::optional<Refusal> refusal(const ProblemShape& shape) {
  if (shape.exact_friction && (shape.exact_incompressibility || shape.exact_contact))
    return Refusal{{"friction.regularization", shape.exact_contact ? "penalty.dN" : "penalty.d"},
                   "exact friction (its own augmented-Lagrangian loop, scaled by 1/d_N) cannot "
                   "yet be combined with the exact constraints d = 0 or d_N = 0 (Uzawa steps)",
                   "use friction.regularization = \"regularized\", or penalty.d > 0 and "
                   "penalty.dN > 0"};
  if (shape.exact_stick && !shape.exact_friction)
    return Refusal{{"friction.regularization", "friction.stick"},
                   "friction.stick = \"exact\" holds the stuck points of the exact law; the "
                   "regularised law has none",
                   "use friction.regularization = \"none\", or friction.stick = \"augmented\""};
  if (shape.exact_stick && !shape.nodal_contact)
    return Refusal{{"contact.normals", "friction.stick"},
                   "friction.stick = \"exact\" needs one friction multiplier per Γ3 node "
                   "(with face Gauss points the stuck tractions are not unique)",
                   "use contact.normals = \"nodes\", or friction.stick = \"augmented\""};
  if (shape.global_pressure && shape.exact_friction)
    return Refusal{{pressure_key(shape), "friction.regularization"},
                   fmt::format("exact friction (its augmented-Lagrangian loop runs the CHOLMOD "
                               "secant solve) is not wired to the {} saddle-point solve",
                               shape.discontinuous_saddle_point ? "mixed" : "Taylor–Hood"),
                   shape.discontinuous_saddle_point
                       ? "use friction.regularization = \"regularized\", or "
                         "formulation.discontinuous_pressure = \"condensed\""
                       : "use friction.regularization = \"regularized\", or "
                         "formulation.pressure = \"P1disc\""};
  return std::nullopt;
}

/// The loop of a shape that is served (refusal(shape) is empty).
LoopKind served_loop(const ProblemShape& shape) {
  const bool newton = shape.method == NonlinearMethod::Newton;
  // Newton's system: the penalty problem, or the mixed one with its pressure
  // condensed at d > 0 (a fixed matrix per cell, linear in u).
  const bool condensed =
      !shape.exact_incompressibility && !shape.exact_contact && !shape.global_pressure;
  if (shape.exact_friction)
    return newton && condensed ? LoopKind::AugmentedNewton : LoopKind::AugmentedSecant;
  if (shape.global_pressure) return LoopKind::SaddlePointSecant;
  if ((shape.mixed && shape.exact_incompressibility) || shape.exact_contact)
    return LoopKind::UzawaSecant;
  return newton ? LoopKind::Newton : LoopKind::Secant;
}

} // namespace

std::variant<LoopKind, Refusal> choose_loop(const ProblemShape& shape) {
  if (auto refused = refusal(shape)) return std::move(*refused);
  const LoopKind loop = served_loop(shape);
  if (shape.exact_stick && loop != LoopKind::AugmentedNewton)
    return Refusal{{"solver.method", "friction.stick"},
                   "friction.stick = \"exact\" is a semismooth Newton: the secant loop (or "
                   "a mixed formulation without a condensed pressure) has no Newton step to "
                   "constrain",
                   "use solver.method = \"newton\" (penalty, or mixed with d > 0), or "
                   "friction.stick = \"augmented\""};
  if (shape.linear_given && !can_serve(shape.linear, loop_storage(loop)))
    return Refusal{{"solver.linear", pressure_key(shape)},
                   fmt::format("{} (Cholesky LLᵀ) cannot factorise the indefinite {} "
                               "saddle-point system",
                               linear_solver_name(shape.linear),
                               shape.discontinuous_saddle_point ? "mixed" : "Taylor–Hood"),
                   shape.discontinuous_saddle_point
                       ? "use solver.linear = \"umfpack\" (LU) or \"petsc\", or "
                         "formulation.discontinuous_pressure = \"condensed\""
                       : "use solver.linear = \"umfpack\" (LU), or a discontinuous pressure "
                         "(formulation.pressure = \"P1disc\" or \"P0\")"};
  return loop;
}

bool exact_stick_serves(ProblemShape shape) {
  if (!shape.exact_friction) return false;
  shape.exact_stick = true;
  shape.nodal_contact = true;
  const auto loop = choose_loop(shape);
  return std::holds_alternative<LoopKind>(loop) &&
         std::get<LoopKind>(loop) == LoopKind::AugmentedNewton;
}

MatrixStorage loop_storage(LoopKind loop) {
  return loop == LoopKind::SaddlePointSecant ? MatrixStorage::Full : MatrixStorage::SymmetricLower;
}

LinearSolverKind linear_solver_for(LoopKind loop, const ProblemShape& shape) {
  return can_serve(shape.linear, loop_storage(loop)) ? shape.linear : LinearSolverKind::Umfpack;
}

std::string loop_name(LoopKind loop, const ProblemShape& shape) {
  switch (loop) {
  case LoopKind::Secant: return "secant";
  case LoopKind::Newton: return "newton";
  case LoopKind::UzawaSecant: return "uzawa around secant";
  case LoopKind::SaddlePointSecant:
    return fmt::format("saddle point ({}) {}around secant",
                       linear_solver_name(linear_solver_for(loop, shape)),
                       shape.exact_contact ? "with uzawa contact " : "");
  case LoopKind::AugmentedSecant: return "augmented-lagrangian friction around secant";
  case LoopKind::AugmentedNewton:
    return shape.exact_stick ? "semismooth newton friction (exact stick at the nodes)"
                             : "augmented-lagrangian friction around newton";
  }
  return "unknown";
}

} // namespace formflow::solvers
