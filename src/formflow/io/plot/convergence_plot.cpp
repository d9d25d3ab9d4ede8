// SPDX-License-Identifier: MIT
// convergence.png/.svg: relative change per iteration against the tolerance, and the pressure.
#include "formflow/io/plot/pictures.hpp"
#include "formflow/io/plot/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace formflow::io::plot {

namespace {

const Rgb change_colour{0.12, 0.31, 0.61};
const Rgb ram_pressure_colour{0.85, 0.37, 0.01};
const Rgb tolerance_colour{0.75, 0.1, 0.1};

/// Whole iterations only: a fractional tick on an iteration axis is noise.
Axis iteration_axis(int last) {
  // A little room after the last iteration so its marker does not sit on the frame.
  Axis axis{0.0, std::max(1.0, last + std::max(1.0, 0.03 * last)), false, {}, "iteration"};
  axis.ticks = linear_ticks(axis.lo, axis.hi, 8);
  std::erase_if(axis.ticks, [](double tick) { return tick != std::round(tick); });
  return axis;
}

Axis change_axis(const std::vector<solvers::IterationRecord>& history, double tolerance) {
  double low = tolerance > 0 ? tolerance : 1.0, high = low;
  for (const auto& record : history)
    if (record.relative_change > 0) {
      low = std::min(low, record.relative_change);
      high = std::max(high, record.relative_change);
    }
  // Whole decades with a margin, so the tolerance line never sits on the frame.
  return Axis{std::pow(10.0, std::floor(std::log10(low) - 0.3)),
              std::pow(10.0, std::ceil(std::log10(high) + 0.3)),
              true,
              {},
              "relative change ‖u^{n+1} − u^{n}‖ / ‖u^{n+1}‖"};
}

Axis pressure_axis(const std::vector<solvers::IterationRecord>& history) {
  auto [low, high] =
      std::minmax_element(history.begin(), history.end(),
                          [](const auto& a, const auto& b) { return a.pressure < b.pressure; });
  const double span = std::max(high->pressure - low->pressure, 1e-3 * std::abs(high->pressure));
  return Axis{low->pressure - 0.08 * span,
              high->pressure + 0.08 * span,
              false,
              {},
              "pressure (ram reaction / height)"};
}

void draw_markers(const Canvas& canvas, const std::vector<Pixel>& points, const Rgb& colour) {
  // Markers only while they stay apart; on long histories they would merge into a band.
  if (points.size() > 80) return;
  for (const Pixel& point : points) canvas.circle(point, 2.6, colour);
}

} // namespace

void draw_convergence(const Canvas& canvas, const PictureData& data) {
  draw_title(canvas, "Convergence of the secant iteration",
             run_description(data.case_, data.results));
  const auto& history = data.results.history;
  const double tolerance = data.case_.solver.tolerance;
  if (history.empty()) {
    Axes(graph_area(), Axis{}, Axis{}).draw(canvas, false);
    draw_no_data(canvas, graph_area(), "no iterations recorded");
    return;
  }
  const Axis x = iteration_axis(history.back().iteration);
  const Axes change(graph_area(), x, change_axis(history, tolerance));
  const Axes pressure(graph_area(), x, pressure_axis(history));
  change.draw(canvas, true);
  pressure.draw_right(canvas, ram_pressure_colour);
  const Rect& area = change.area();

  canvas.clip(area);
  const double y_tolerance = change.py(tolerance);
  canvas.line({area.x, y_tolerance}, {area.right(), y_tolerance},
              {1.6, tolerance_colour, 1.0, 9.0});
  std::vector<Pixel> change_points, pressure_points;
  for (const auto& record : history) {
    // A zero change (an exact fixed point) cannot sit on a log axis: drawn at the bottom.
    const double value = record.relative_change > 0 ? record.relative_change : change.y_axis().lo;
    change_points.push_back(change.at(record.iteration, value));
    pressure_points.push_back(pressure.at(record.iteration, record.pressure));
  }
  canvas.polyline(pressure_points, {1.8, ram_pressure_colour});
  draw_markers(canvas, pressure_points, ram_pressure_colour);
  canvas.polyline(change_points, {2.0, change_colour});
  draw_markers(canvas, change_points, change_colour);
  canvas.unclip();

  const std::vector<LegendEntry> legend = {
      {"relative change (left axis)", {2.0, change_colour}},
      {fmt::format("tolerance δ = {:g}", tolerance), {1.6, tolerance_colour, 1.0, 9.0}},
      {"pressure (right axis)", {1.8, ram_pressure_colour}}};
  draw_legend(canvas, {area.right() - 10, area.y + 10}, legend);
}

} // namespace formflow::io::plot
