// SPDX-License-Identifier: MIT
// Monitor lines with an estimate of the time left.
#include "formflow/app/monitor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace formflow::app {

void Monitor::header() const {
  fmt::print(out_, "{:>5}  {:>12}  {:>12}  {:>9}  {:>9}{}\n", "iter", "rel.change", "pressure",
             "time[s]", "left[s]", krylov_ ? fmt::format("  {:>7}", "krylov") : "");
  std::fflush(out_);
}

void Monitor::operator()(const solvers::IterationRecord& record) {
  if (record.coupling > 0) {
    // Hot forming: the line that closes a staggered step (the flow solve's own lines
    // came before it); the flow iterations restart their estimate after it.
    elapsed_ += record.seconds;
    recent_changes_.clear();
    fmt::print(out_,
               "coupling {:>3}  ΔT/rise {:>10.3e}  Δp/p {:>10.3e}  pressure {:>12.6f}  "
               "T_max {:>10.3f}\n",
               record.coupling, record.relative_change, record.force_change, record.pressure,
               record.max_temperature);
    std::fflush(out_);
    return;
  }
  if (record.stage != stage_) {
    stage_ = record.stage;
    recent_changes_.clear();
    fmt::print(out_, "  -- {}\n", stage_.empty() ? std::string("the run's solve") : stage_);
  }
  elapsed_ += record.seconds;
  constexpr std::size_t window = 5;
  recent_changes_.push_back(record.relative_change);
  if (recent_changes_.size() > window) recent_changes_.pop_front();
  // Linear convergence: change_n ≈ ρⁿ, with ρ the geometric mean contraction
  // over the window; iterations left ≈ log(δ/change)/log ρ.
  std::string left = "-";
  const auto steps = static_cast<Real>(recent_changes_.size() - 1);
  const Real rate = steps > 0 && recent_changes_.front() > 0
                        ? std::pow(record.relative_change / recent_changes_.front(), 1.0 / steps)
                        : 0.0;
  if (rate > 0 && rate < 1 && record.relative_change > tolerance_) {
    const Real remaining = std::log(tolerance_ / record.relative_change) / std::log(rate);
    // The run stops at max_iterations whether or not it has converged by then.
    const Real iterations_left = std::max(0, max_iterations_ - record.iteration);
    left = fmt::format("{:.2f}", std::min(remaining, iterations_left) * record.seconds);
  }
  // An iterative back-end's Krylov iterations in this step (solver.linear = "petsc").
  const std::string krylov =
      krylov_ ? fmt::format("  {:>7}", record.linear_iterations < 0
                                           ? std::string("-")
                                           : std::to_string(record.linear_iterations))
              : std::string();
  fmt::print(out_, "{:>5}  {:>12.4e}  {:>12.6f}  {:>9.3f}  {:>9}{}\n", record.iteration,
             record.relative_change, record.pressure, elapsed_, left, krylov);
  std::fflush(out_);
}

} // namespace formflow::app
