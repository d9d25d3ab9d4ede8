// SPDX-License-Identifier: MIT
// The `formflow study` subcommand: progress lines, files, exit code.
#include "formflow/app/cli.hpp"
#include "formflow/app/stop_signals.hpp"
#include "formflow/app/study.hpp"
#include "formflow/io/output_directory.hpp"
#include "formflow/io/study_files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <set>

namespace formflow::app {

namespace {

std::string cell(const std::optional<Real>& value, const char* format) {
  if (!value || !std::isfinite(*value)) return "-";
  return fmt::format(fmt::runtime(format), *value);
}

} // namespace

int study_command(const StudyCommand& command) {
  const StudyPlan plan = plan_study(command.case_path, command.vary, command.overrides);
  // Before the first rung: a -o that cannot take the files costs nothing (exit 2).
  io::check_output_directory(command.output_directory, io::study_file_names());
  // Rungs share the case file and --set keys, and mostly their warnings: print each once.
  std::set<std::string> warnings;
  for (const io::Case& rung : plan.cases)
    for (const std::string& warning : rung.warnings)
      if (warnings.insert(warning).second) fmt::print(stderr, "warning: {}\n", warning);
  if (!command.quiet)
    fmt::print(
        "formflow study of {} over {} rungs ({})\n{:>12} {:>9} {:>5} {:>11} {:>12} {:>12} {:>10}\n",
        plan.key, plan.values.size(), plan.description, plan.key, "dofs", "its", "pressure",
        "error/diff V", "error/diff L2", "status");
  auto progress = [&command](const post::StudyRung& rung) {
    if (command.quiet) return;
    const auto& norms = rung.error ? rung.error : rung.difference;
    fmt::print("{:>12} {:>9} {:>5} {:>11.6f} {:>12} {:>12} {:>10}\n", rung.value_text, rung.dofs,
               rung.iterations, rung.pressure.ram_reaction,
               cell(norms ? std::optional<Real>(norms->v_norm) : std::nullopt, "{:.4e}"),
               cell(norms ? std::optional<Real>(norms->l2) : std::nullopt, "{:.4e}"),
               solvers::stop_reason_name(rung.stop_reason));
    std::fflush(stdout);
  };
  post::StudyTable table = run_study(plan, command.estimate_condition, progress,
                                     [](const solvers::IterationRecord&) { throw_if_signalled(); });
  table.exact_load = command.exact_load;
  io::write_study(command.output_directory, table, signal_stop_request());
  if (stop_signal() != 0) {
    fmt::print(stderr, "formflow: stopped by a signal; the study in {} is complete\n",
               command.output_directory);
    return signal_exit_code(stop_signal());
  }
  if (!command.quiet) {
    fmt::print("observed orders (between a rung and the one before it):\n");
    for (const post::StudyRung& rung : table.rungs)
      fmt::print("{:>12}  V {:>6}  L2 {:>6}  pressure {:>6}  Richardson {:>9}{}\n", rung.value_text,
                 cell(rung.order_v, "{:.3f}"), cell(rung.order_l2, "{:.3f}"),
                 cell(rung.pressure_order, "{:.3f}"), cell(rung.pressure_extrapolated, "{:.5f}"),
                 rung.reciprocal_condition
                     ? fmt::format("  rcond {:.3e}", *rung.reciprocal_condition)
                     : "");
    for (std::size_t k = 0; k < table.adaptive.cycles.size(); ++k) {
      const post::AdaptCycle& cycle = table.adaptive.cycles[k];
      fmt::print("adaptive cycle {}: {} dofs, p = {:.6f}, estimate {}{}\n", k, cycle.dofs,
                 cycle.load, cell(cycle.estimate, "{:.4e}"),
                 cycle.refined_mesh ? " (the refined mesh)" : "");
    }
    if (!table.adaptive.cycles.empty()) fmt::print("adaptive: {}\n", table.adaptive.stop);
    fmt::print("study written to {}/study.csv, study.png, study.svg{}\n", command.output_directory,
               table.has_load_errors() ? ", load_error_dofs.png, adaptive.csv" : "");
  }
  if (!table.all_converged()) {
    fmt::print(stderr,
               "formflow: NOT CONVERGED: some rungs of the study did not converge; they "
               "are marked in {}/study.csv (stop_reason) and study.png\n",
               command.output_directory);
    return NotConverged;
  }
  return Ok;
}

} // namespace formflow::app
