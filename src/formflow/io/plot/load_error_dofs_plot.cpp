// SPDX-License-Identifier: MIT
// load_error_dofs.png/.svg: the load's error (true or estimated) against dofs.
#include "formflow/io/plot/load_error_dofs_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace formflow::io::plot {

namespace {

/// One refinement sequence: dofs, load and estimate per mesh.
struct LoadSequence {
  std::string label;
  Rgb colour;
  std::vector<double> dofs, load;
  std::vector<std::optional<double>> estimate;
  /// The reference slope's order in 1/dofs: ½ for uniform refinement (first order in
  /// h around the die corner), 1 for the adaptive cycles (docs/error-estimation.md).
  double reference_order = 0.5;
};

const Rgb uniform_colour{0.12, 0.31, 0.61};
const Rgb adaptive_colour{0.85, 0.37, 0.01};
const Rgb reference_colour{0.45, 0.45, 0.45};

/// The value drawn for a mesh: |p_h − p| with an exact load, else the estimate.
std::optional<double> drawn_error(const LoadSequence& sequence, std::size_t k,
                                  std::optional<double> exact) {
  const std::optional<double> value =
      exact ? std::optional<double>(std::abs(sequence.load[k] - *exact)) : sequence.estimate[k];
  if (!value || !std::isfinite(*value) || *value <= 0) return std::nullopt;
  return value;
}

std::vector<LoadSequence> sequences(const post::StudyTable& table) {
  LoadSequence uniform{"uniform refinement", uniform_colour, {}, {}, {}, 0.5};
  for (const post::StudyRung& rung : table.rungs)
    if (rung.converged()) {
      uniform.dofs.push_back(static_cast<double>(rung.dofs));
      uniform.load.push_back(rung.pressure.ram_reaction);
      uniform.estimate.push_back(rung.load_error_estimate);
    }
  LoadSequence adaptive{"adaptive refinement", adaptive_colour, {}, {}, {}, 1.0};
  for (const post::AdaptCycle& cycle : table.adaptive.cycles) {
    adaptive.dofs.push_back(static_cast<double>(cycle.dofs));
    adaptive.load.push_back(cycle.load);
    adaptive.estimate.push_back(cycle.estimate);
  }
  std::vector<LoadSequence> all;
  for (LoadSequence* sequence : {&uniform, &adaptive})
    if (!sequence->dofs.empty()) all.push_back(std::move(*sequence));
  return all;
}

/// Whole decades around [lo, hi] with a margin (as the study picture's axes).
Axis log_axis(double lo, double hi, std::string label) {
  return Axis{std::pow(10.0, std::floor(std::log10(lo) - 0.15)),
              std::pow(10.0, std::ceil(std::log10(hi) + 0.15)),
              true,
              {},
              std::move(label)};
}

} // namespace

void draw_load_error_against_dofs(const Canvas& canvas, const post::StudyTable& table) {
  const std::optional<double> exact = table.exact_load;
  draw_title(canvas, "Load error against dofs",
             exact ? fmt::format("|p_{{h}} − p|, p = {:.6g}; bars: the estimates", *exact)
                   : std::string("the estimates of |p_{h} − p| (no exact load given)"));
  const std::vector<LoadSequence> all = sequences(table);
  double x_lo = std::numeric_limits<double>::max(), x_hi = 0;
  double y_lo = std::numeric_limits<double>::max(), y_hi = 0;
  for (const LoadSequence& sequence : all)
    for (std::size_t k = 0; k < sequence.dofs.size(); ++k) {
      const std::optional<double> value = drawn_error(sequence, k, exact);
      if (!value) continue;
      x_lo = std::min(x_lo, sequence.dofs[k]), x_hi = std::max(x_hi, sequence.dofs[k]);
      y_lo = std::min(y_lo, *value), y_hi = std::max(y_hi, *value);
      if (const std::optional<double> bar = sequence.estimate[k]; bar && *bar > 0)
        y_lo = std::min(y_lo, *bar), y_hi = std::max(y_hi, *bar);
    }
  if (x_hi <= 0) {
    Axes(graph_area(), Axis{}, Axis{}).draw(canvas, false);
    draw_no_data(canvas, graph_area(), "no load error to draw");
    return;
  }
  const Axes axes(graph_area(), log_axis(x_lo, x_hi, "dofs"),
                  log_axis(y_lo, y_hi, exact ? "|p_{h} − p|" : "estimate of |p_{h} − p|"));
  axes.draw(canvas, true);
  const Rect& area = axes.area();
  std::vector<LegendEntry> legend;
  canvas.clip(area);
  for (const LoadSequence& sequence : all) {
    std::vector<Pixel> points;
    std::size_t last = 0;
    for (std::size_t k = 0; k < sequence.dofs.size(); ++k)
      if (const std::optional<double> value = drawn_error(sequence, k, exact)) {
        points.push_back(axes.at(sequence.dofs[k], *value));
        last = k;
      }
    if (points.empty()) continue;
    canvas.polyline(points, {2.0, sequence.colour});
    const Stroke bar{1.4, sequence.colour, 0.8};
    for (std::size_t k = 0; k < sequence.dofs.size(); ++k) {
      const std::optional<double> value = drawn_error(sequence, k, exact);
      if (!value) continue;
      const Pixel point = axes.at(sequence.dofs[k], *value);
      canvas.circle(point, 3.4, sequence.colour);
      // The estimate's bar: from the dot to a cap at the estimate (with an exact load).
      if (const std::optional<double> estimate = sequence.estimate[k];
          exact && estimate && *estimate > 0) {
        const Pixel cap = axes.at(sequence.dofs[k], *estimate);
        canvas.line(point, cap, bar);
        canvas.line(Pixel{cap[0] - 5, cap[1]}, Pixel{cap[0] + 5, cap[1]}, bar);
      }
    }
    legend.push_back(
        {fmt::format("{} ({} meshes)", sequence.label, points.size()), {2.0, sequence.colour}});
    // Reference slope through the sequence's finest drawn point: dofs^(−1/2) for
    // the uniform ladder (first order in h), dofs^(−1) for the adaptive cycles.
    const double order = sequence.reference_order;
    const double x_a = sequence.dofs[last], y_a = *drawn_error(sequence, last, exact);
    const double x0 = axes.x_axis().lo, x1 = axes.x_axis().hi;
    const Stroke dashed{1.2, sequence.colour, 0.6, 7.0};
    canvas.line(axes.at(x0, y_a * std::pow(x0 / x_a, -order)),
                axes.at(x1, y_a * std::pow(x1 / x_a, -order)), dashed);
    legend.push_back({fmt::format("slope dofs^{{−{}}}", order == 0.5 ? "1/2" : "1"), dashed});
  }
  canvas.unclip();
  if (exact) legend.push_back({"bar to the cap: the estimate", {1.4, reference_colour, 0.8}});
  draw_legend(canvas, {area.right() - 10, area.y + 10}, legend);
}

Picture render_load_error_dofs_plot(const post::StudyTable& table) {
  auto draw = [&table](Canvas& canvas) { draw_load_error_against_dofs(canvas, table); };
  return Picture{"load_error_dofs", render_png(picture_width, picture_height, draw),
                 render_svg(picture_width, picture_height, draw)};
}

} // namespace formflow::io::plot
