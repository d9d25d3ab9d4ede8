// SPDX-License-Identifier: MIT
// `formflow study`: a ladder of runs over one case key, with error norms and observed orders.
#pragma once

#include "formflow/app/simulation.hpp"
#include "formflow/io/case.hpp"
#include "formflow/io/case_keys.hpp"
#include "formflow/post/study_table.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace formflow::app {

/// A validated study: the varied key, its values as given, and each rung's case.
struct StudyPlan {
  std::string key;
  std::vector<std::string> values;
  std::vector<io::Case> cases;
  std::string description; ///< "case, --set overrides" for the plot subtitle
};

/// Most values a study accepts: each is a whole solve (and a load_case while
/// planning), and a log-log ladder needs a handful.
inline constexpr std::size_t max_study_rungs = 64;

/// Parses `vary` ("key=v1,v2,..."; a value may be a fraction "10/6") and loads
/// the case with `overrides` and then key=value for every value, so that every
/// input error surfaces before anything runs. The key must be a real or integer
/// key, the values positive (they are the x axis of a log-log plot), at least two
/// and at most max_study_rungs.
/// Throws InputError.
StudyPlan plan_study(const std::string& case_path, const std::string& vary,
                     const std::vector<io::Override>& overrides);

/// The value of the real or integer `key` in `case_`, as a Real.
Real numeric_key_value(const io::CaseKey& key, const io::Case& case_);

/// Solves every rung in order. A mesh.size study of a case with [adapt] runs the rungs
/// without it (the uniform ladder, each with the load's estimate) and then the
/// adaptive run from the first rung's case, recorded in `adaptive`. Rungs with the same mesh as the
/// last one also get ‖u − u_last‖ (the last rung is the reference of a penalty or regularisation
/// ladder). `estimate_condition` adds CHOLMOD's rcond of K(u). `on_rung` is called after each rung
/// (for progress lines), `on_iteration` after every nonlinear iteration of every rung (a safe point
/// to stop at).
post::StudyTable run_study(const StudyPlan& plan, bool estimate_condition,
                           const std::function<void(const post::StudyRung&)>& on_rung = {},
                           const IterationCallback& on_iteration = {});

} // namespace formflow::app

namespace formflow::app {

/// What `formflow study` was asked to do.
struct StudyCommand {
  std::string case_path;
  std::string vary;
  std::vector<io::Override> overrides;
  std::string output_directory = "study";
  bool estimate_condition = false;
  bool quiet = false;
  /// The exact load p (--exact-load): the picture of the load error against dofs then
  /// shows |p_h − p| with each estimate's bar, not the estimate alone.
  std::optional<Real> exact_load;
};

/// Plans (exit 2 on bad input, nothing written), runs with one progress line
/// per rung (and per adaptive cycle), writes DIR/study.csv, study.png, study.svg
/// (with load error estimates also load_error_dofs.png/.svg and adaptive.csv); returns 3 if a rung
/// did not converge (files still written, the rung marked), else 0.
/// InputError propagates to the caller, which turns it into exit 2.
int study_command(const StudyCommand& command);

} // namespace formflow::app
