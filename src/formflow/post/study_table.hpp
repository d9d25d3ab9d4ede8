// SPDX-License-Identifier: MIT
// The rows of a parameter study (a ladder of runs) and the observed orders between rungs.
#pragma once

#include "formflow/post/adaptivity.hpp"
#include "formflow/post/corner_profile.hpp"
#include "formflow/post/error_norms.hpp"
#include "formflow/post/results.hpp"

#include <optional>
#include <string>
#include <vector>

namespace formflow::post {

/// One run of a study.
struct StudyRung {
  std::string value_text; ///< the varied key's value as given
  Real parameter = 0.0;   ///< its numeric value (> 0: the x axis of the log-log plot)
  Index dofs = 0;
  int iterations = 0;
  solvers::StopReason stop_reason = solvers::StopReason::MaxIterations;
  Real seconds = 0.0;
  Pressures pressure;
  std::optional<ErrorNorms> error;      ///< against the exact field (manufactured solutions)
  std::optional<ErrorNorms> difference; ///< ‖u − u_last‖ when every rung has the same mesh
  std::optional<Real> reciprocal_condition; ///< CHOLMOD rcond of K(u), when asked for
  /// Observed orders against the parameter between the previous rung and this
  /// one, ln(e_k/e_{k−1}) / ln(p_k/p_{k−1}), of `error` (or else of `difference`).
  std::optional<Real> order_v, order_l2;
  /// Observed order of the ram-reaction pressure from this and the two
  /// previous rungs, and the Richardson limit it implies (geometric ladders).
  std::optional<Real> pressure_order, pressure_extrapolated;
  /// ε̄̇ around the die corner (forming cases of a mesh.size study).
  std::optional<CornerProfile> corner;
  /// The estimate of |p_h − p| (solver.load_error; docs/error-estimation.md), when computed.
  std::optional<Real> load_error_estimate;

  bool converged() const { return stop_reason == solvers::StopReason::Converged; }
};

struct StudyTable {
  std::string key;         ///< the varied case key ("mesh.size")
  std::string description; ///< one line: which case, which fixed overrides
  std::vector<StudyRung> rungs;
  /// The order theory predicts for the V and L2 norms of this ladder (drawn
  /// as reference slopes), when known: Theorem 4.1 for a manufactured
  /// solution on a mesh ladder, 3.4 for penalty.d, the bound of 3.3 for penalty.dT.
  std::optional<Real> theory_order_v, theory_order_l2;
  /// The exact load p (`formflow study --exact-load`): |p_h − p| is drawn against dofs.
  std::optional<Real> exact_load;
  /// A mesh.size study of a case with [adapt]: its adaptive run from the first rung's
  /// case, every cycle (the rungs themselves run without [adapt]: the uniform ladder).
  AdaptRecord adaptive;

  bool all_converged() const;
  bool has_errors() const { return !rungs.empty() && rungs.front().error.has_value(); }
  bool has_differences() const;
  bool has_corner_profiles() const { return !rungs.empty() && rungs.front().corner.has_value(); }
  /// Some rung, or the adaptive run, has a load error estimate: the picture of the
  /// load error against dofs is drawn.
  bool has_load_errors() const;
};

/// Fills order_v, order_l2, pressure_order and pressure_extrapolated of every
/// rung from the rows before it; a rung that did not converge gets none and
/// breaks the three-rung pressure estimate.
void compute_orders(StudyTable& table);

/// ln(e_k/e_{k−1}) / ln(p_k/p_{k−1}); nullopt unless all four are finite and positive, p_k ≠
/// p_{k−1}.
std::optional<Real> observed_order(Real p_previous, Real e_previous, Real p, Real e);

} // namespace formflow::post
