// SPDX-License-Identifier: MIT
// Anderson acceleration of a fixed-point iteration x = G(x) (Walker & Ni, SIAM J. Numer.
// Anal. 49 (2011), "type II" with unit damping): the next iterate mixes the last m images
// G(xₖ) with the weights that minimise the mixed residual f = G(x) − x in the least-squares
// sense. Used by the secant loop (solvers/secant_iteration.hpp, solver.acceleration).
//
// Not a library gap: the whole method is a ring of m difference columns and one small
// least-squares problem (n × m, m ≤ 10) per step, which Eigen's column-pivoting QR solves;
// PETSc's SNESAnderson would only serve the PETSc path, and the loop owns the choices that
// matter here (which steps are mixed, when the history is void).
#pragma once

#include "formflow/core/types.hpp"
#include "formflow/solvers/nonlinear_problem.hpp"

#include <deque>
#include <optional>

namespace formflow::solvers {

/// Above this condition estimate of the least-squares matrix (the difference columns'
/// R factor, |r₁₁|/|r_cc|) the mixing weights are noise: the columns carry the linear
/// solves' errors (relative 1e-8–1e-12 exact, 1e-2 of the residual for a loose step) and
/// the weights' error is that times the condition. 1/√ε: where a column-pivoting QR still
/// holds half the digits; beyond it the history is dropped (Walker & Ni restart).
inline constexpr Real anderson_max_condition = 1e8;

/// The history of one fixed-point iteration x ↦ G(x) on vectors of a fixed size, and
/// the next iterate it proposes. Depth m: at most m difference columns.
class AndersonAcceleration {
public:
  /// `ghosted`: a distributed run's problem, whose vectors each rank holds in part
  /// (NonlinearProblem::ghosted): the norms and the least-squares problem then run over
  /// the ranks' owned rows (its dot and r_factor). Null: whole vectors.
  explicit AndersonAcceleration(int depth, const NonlinearProblem* ghosted = nullptr);

  /// After G mapped `iterate` to `image`: records the pair and returns the next iterate,
  /// image − ΔG γ with γ = argmin ‖f − ΔF γ‖ (f = image − iterate; ΔF, ΔG the differences
  /// of consecutive residuals and images), or `image` itself (the plain step) when
  /// `may_mix` is false, no difference is recorded yet, or a safeguard restarted the
  /// history: the last mix did not reduce ‖f‖ (a plain step of a contraction would), or
  /// the least-squares problem is worse conditioned than anderson_max_condition.
  VectorX next(const VectorX& iterate, const VectorX& image, bool may_mix = true);

  /// Forgets every pair: the map G changed (an inner multiplier loop moved, the
  /// problem's after-iteration state was updated), older pairs belong to another map.
  void forget();

  /// Difference columns the last next() mixed (0: it returned the plain image).
  int last_columns() const { return last_columns_; }
  /// How often a safeguard dropped the history.
  int restarts() const { return restarts_; }

private:
  void restart();

  Real norm(const VectorX& v) const { return ghosted_ ? ghosted_->norm(v) : v.norm(); }
  /// γ = argmin ‖f − ΔF γ‖ over the ranks' rows, or nothing when the safeguard restarts.
  std::optional<VectorX> ghosted_weights(Index columns);

  int depth_;
  const NonlinearProblem* ghosted_ = nullptr;
  std::deque<VectorX> residual_differences_, image_differences_;
  VectorX last_residual_, last_image_; ///< empty: no pair recorded
  bool last_mixed_ = false;
  int last_columns_ = 0;
  int restarts_ = 0;
};

} // namespace formflow::solvers
