// SPDX-License-Identifier: MIT
// Observed orders of convergence and Richardson extrapolation along a study.
#include "formflow/post/study_table.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::post {

bool StudyTable::all_converged() const {
  return std::all_of(rungs.begin(), rungs.end(), [](const StudyRung& r) { return r.converged(); });
}

bool StudyTable::has_differences() const {
  return std::any_of(rungs.begin(), rungs.end(),
                     [](const StudyRung& r) { return r.difference.has_value(); });
}

bool StudyTable::has_load_errors() const {
  const auto estimated = [](const StudyRung& r) { return r.load_error_estimate.has_value(); };
  const auto cycle_estimated = [](const AdaptCycle& c) { return c.estimate.has_value(); };
  return std::any_of(rungs.begin(), rungs.end(), estimated) ||
         std::any_of(adaptive.cycles.begin(), adaptive.cycles.end(), cycle_estimated);
}

std::optional<Real> observed_order(Real p_previous, Real e_previous, Real p, Real e) {
  const bool usable = std::isfinite(p_previous) && std::isfinite(e_previous) && std::isfinite(p) &&
                      std::isfinite(e) && p_previous > 0 && e_previous > 0 && p > 0 && e > 0 &&
                      p != p_previous;
  if (!usable) return std::nullopt;
  return std::log(e / e_previous) / std::log(p / p_previous);
}

namespace {

/// Pressure order q from P_{k−2}, P_{k−1}, P_k with a constant parameter ratio
/// r = p_{k−1}/p_k, and the limit P∞ = P_k + (P_k − P_{k−1})/(r^q − 1).
void pressure_estimate(const StudyRung& first, const StudyRung& second, StudyRung& third) {
  const Real ratio_a = first.parameter / second.parameter;
  const Real ratio_b = second.parameter / third.parameter;
  if (std::abs(ratio_a - ratio_b) > 1e-6 * ratio_b || std::abs(std::log(ratio_b)) < 1e-12) return;
  const Real step_a = second.pressure.ram_reaction - first.pressure.ram_reaction;
  const Real step_b = third.pressure.ram_reaction - second.pressure.ram_reaction;
  if (!(step_a * step_b > 0)) return; // not monotone: no asymptotic range yet
  const Real order = std::log(step_a / step_b) / std::log(ratio_b);
  third.pressure_order = order;
  const Real denominator = std::pow(ratio_b, order) - 1.0;
  if (std::abs(denominator) > 1e-12)
    third.pressure_extrapolated = third.pressure.ram_reaction + step_b / denominator;
}

} // namespace

void compute_orders(StudyTable& table) {
  auto& rungs = table.rungs;
  for (std::size_t k = 1; k < rungs.size(); ++k) {
    StudyRung& rung = rungs[k];
    const StudyRung& previous = rungs[k - 1];
    if (!rung.converged() || !previous.converged()) continue;
    const std::optional<ErrorNorms>& now = rung.error ? rung.error : rung.difference;
    const std::optional<ErrorNorms>& before = previous.error ? previous.error : previous.difference;
    if (now && before) {
      rung.order_v =
          observed_order(previous.parameter, before->v_norm, rung.parameter, now->v_norm);
      rung.order_l2 = observed_order(previous.parameter, before->l2, rung.parameter, now->l2);
    }
    if (k >= 2 && rungs[k - 2].converged()) pressure_estimate(rungs[k - 2], previous, rung);
  }
}

} // namespace formflow::post
