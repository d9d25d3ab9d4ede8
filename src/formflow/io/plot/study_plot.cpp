// SPDX-License-Identifier: MIT
// study.png/.svg: convergence of a ladder on log-log axes with reference slopes.
#include "formflow/io/plot/study_plot.hpp"

#include "formflow/io/plot/ticks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace formflow::io::plot {

namespace {

/// Which norm a series shows (the theory order differs between V and L2).
enum class SeriesKind { V, L2, Other };

struct Series {
  std::string label;
  Rgb colour;
  std::vector<double> x, y;
  std::vector<bool> converged;
  SeriesKind kind = SeriesKind::Other;
};

const Rgb palette[] = {{0.12, 0.31, 0.61}, {0.85, 0.37, 0.01}, {0.2, 0.55, 0.2}, {0.5, 0.3, 0.6}};
const Rgb failed_colour{0.8, 0.1, 0.1};
const Rgb slope_colour{0.45, 0.45, 0.45};

/// Adds a series of the positive, finite values `value(rung)` returns.
template <class Value>
void add_series(std::vector<Series>& all, const post::StudyTable& table, std::string label,
                Value value, SeriesKind kind = SeriesKind::Other) {
  Series series{std::move(label), palette[all.size() % 4], {}, {}, {}, kind};
  for (const post::StudyRung& rung : table.rungs)
    if (const std::optional<double> y = value(rung); y && std::isfinite(*y) && *y > 0) {
      series.x.push_back(rung.parameter);
      series.y.push_back(*y);
      series.converged.push_back(rung.converged());
    }
  if (series.x.size() >= 1) all.push_back(std::move(series));
}

std::vector<Series> norm_series(const post::StudyTable& table, bool* log_y) {
  std::vector<Series> all;
  *log_y = true;
  if (table.has_errors()) {
    add_series(
        all, table, "‖u − u_{h}‖_{V}",
        [](const auto& r) -> std::optional<double> {
          return r.error ? std::optional<double>(r.error->v_norm) : std::nullopt;
        },
        SeriesKind::V);
    add_series(
        all, table, "‖u − u_{h}‖_{L2}",
        [](const auto& r) -> std::optional<double> {
          return r.error ? std::optional<double>(r.error->l2) : std::nullopt;
        },
        SeriesKind::L2);
  } else if (table.has_differences()) {
    add_series(
        all, table, "‖u − u_{ref}‖_{V} (u_{ref}: last rung)",
        [](const auto& r) -> std::optional<double> {
          return r.difference ? std::optional<double>(r.difference->v_norm) : std::nullopt;
        },
        SeriesKind::V);
    add_series(
        all, table, "‖u − u_{ref}‖_{L2}",
        [](const auto& r) -> std::optional<double> {
          return r.difference ? std::optional<double>(r.difference->l2) : std::nullopt;
        },
        SeriesKind::L2);
  }
  add_series(all, table, "rcond of K (CHOLMOD)",
             [](const auto& r) { return r.reciprocal_condition; });
  if (!all.empty()) return all;
  *log_y = false;
  add_series(all, table, "ram reaction pressure",
             [](const auto& r) -> std::optional<double> { return r.pressure.ram_reaction; });
  add_series(all, table, "power balance pressure",
             [](const auto& r) -> std::optional<double> { return r.pressure.power_balance; });
  return all;
}

/// A reference slope and the point it passes through.
struct Slope {
  double order = 0.0;
  std::size_t anchor = 0; ///< index into the series
  bool from_theory = false;
};

/// Without a theoretical order: the most frequent pair order rounded to a
/// half-integer (ties to the finer pairs), through the finer point of the
/// finest pair that has it, so that one polluted end pair does not set it.
/// With one: that order, through the finest point.
std::optional<Slope> reference_slope(const Series& series, std::optional<double> theory) {
  const std::size_t n = series.x.size();
  if (n < 2) return std::nullopt;
  if (theory) return Slope{*theory, n - 1, true};
  std::vector<double> rounded(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 1; k < n; ++k) {
    const double order =
        std::log(series.y[k] / series.y[k - 1]) / std::log(series.x[k] / series.x[k - 1]);
    if (std::isfinite(order) && std::abs(order) >= 0.25) rounded[k] = std::round(order * 2.0) / 2.0;
  }
  std::optional<Slope> best;
  int best_count = 0;
  for (std::size_t k = n - 1; k >= 1; --k) {
    if (!std::isfinite(rounded[k])) continue;
    const int count = static_cast<int>(std::count(rounded.begin(), rounded.end(), rounded[k]));
    if (count > best_count) best = Slope{rounded[k], k, false}, best_count = count;
  }
  return best;
}

Axis range_axis(const std::vector<Series>& all, bool x, bool log, std::string label) {
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (const Series& s : all)
    for (double v : x ? s.x : s.y) lo = std::min(lo, v), hi = std::max(hi, v);
  if (log) {
    // Whole decades with a margin, so the end points never sit on the frame.
    return Axis{std::pow(10.0, std::floor(std::log10(lo) - 0.15)),
                std::pow(10.0, std::ceil(std::log10(hi) + 0.15)),
                true,
                {},
                std::move(label)};
  }
  const double span = std::max(hi - lo, 1e-3 * std::abs(hi));
  return Axis{lo - 0.1 * span, hi + 0.1 * span, false, {}, std::move(label)};
}

/// The description shortened with "…" until it fits the picture width.
std::string fitted_subtitle(const Canvas& canvas, std::string text) {
  const Font font{12.0};
  const double room = canvas.width() - 40.0;
  if (canvas.text_width(text, font) <= room) return text;
  while (!text.empty() && canvas.text_width(text + "…", font) > room) {
    text.pop_back();
    while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80)
      text.pop_back();
    if (!text.empty() && static_cast<unsigned char>(text.back()) >= 0xC0) text.pop_back();
  }
  return text + "…";
}

} // namespace

void draw_study(const Canvas& canvas, const post::StudyTable& table) {
  const bool all_converged = table.all_converged();
  draw_title(
      canvas,
      fmt::format("Study of {}{}", table.key, all_converged ? "" : " (NOT all rungs converged)"),
      fitted_subtitle(canvas, table.description));
  bool log_y = true;
  const std::vector<Series> all = norm_series(table, &log_y);
  if (all.empty()) {
    Axes(graph_area(), Axis{}, Axis{}).draw(canvas, false);
    draw_no_data(canvas, graph_area(), "no finite values");
    return;
  }
  const Axes axes(graph_area(), range_axis(all, true, true, table.key),
                  range_axis(all, false, log_y, log_y ? "norm" : "pressure (per unit ram height)"));
  axes.draw(canvas, true);
  const Rect& area = axes.area();
  std::vector<LegendEntry> legend;
  canvas.clip(area);
  for (const Series& series : all) {
    std::vector<Pixel> points;
    for (std::size_t k = 0; k < series.x.size(); ++k)
      points.push_back(axes.at(series.x[k], series.y[k]));
    canvas.polyline(points, {2.0, series.colour});
    for (std::size_t k = 0; k < points.size(); ++k)
      canvas.circle(points[k], series.converged[k] ? 3.2 : 5.0,
                    series.converged[k] ? series.colour : failed_colour);
    legend.push_back({series.label, {2.0, series.colour}});
    if (!log_y) continue;
    const std::optional<double> theory = series.kind == SeriesKind::V    ? table.theory_order_v
                                         : series.kind == SeriesKind::L2 ? table.theory_order_l2
                                                                         : std::nullopt;
    if (const std::optional<Slope> slope = reference_slope(series, theory)) {
      // y = y_a (x/x_a)^order across the whole x range, dashed.
      const double x_a = series.x[slope->anchor], y_a = series.y[slope->anchor];
      const double x0 = axes.x_axis().lo, x1 = axes.x_axis().hi;
      canvas.line(axes.at(x0, y_a * std::pow(x0 / x_a, slope->order)),
                  axes.at(x1, y_a * std::pow(x1 / x_a, slope->order)),
                  {1.2, series.colour, 0.6, 7.0});
      legend.push_back(
          {fmt::format("{} slope {:g}", slope->from_theory ? "theory" : "observed", slope->order),
           {1.2, series.colour, 0.6, 7.0}});
    }
  }
  if (!log_y && !table.rungs.empty() && table.rungs.back().pressure_extrapolated) {
    const double limit = *table.rungs.back().pressure_extrapolated;
    const double y = axes.py(limit);
    canvas.line({area.x, y}, {area.right(), y}, {1.4, slope_colour, 1.0, 8.0});
    legend.push_back(
        {fmt::format("Richardson limit {:.4f}", limit), {1.4, slope_colour, 1.0, 8.0}});
  }
  canvas.unclip();
  if (!all_converged) legend.push_back({"large red dot: rung not converged", {2.0, failed_colour}});
  // Rising data leave the top-left corner free, falling data the top-right one.
  const Series& first = all.front();
  const bool rising = first.y.size() >= 2 &&
                      (first.y.back() - first.y.front()) * (first.x.back() - first.x.front()) > 0;
  if (rising)
    draw_legend(canvas, {area.x + 10, area.y + 10}, legend, HAlign::Left);
  else
    draw_legend(canvas, {area.right() - 10, area.y + 10}, legend);
}

void draw_corner(const Canvas& canvas, const post::StudyTable& table) {
  draw_title(canvas, "Equivalent strain rate near the die corner",
             fitted_subtitle(canvas, table.description));
  std::vector<Series> all;
  for (const post::StudyRung& rung : table.rungs) {
    if (!rung.corner || rung.corner->radius.empty()) continue;
    Series series{fmt::format("{} = {}", table.key, rung.value_text),
                  palette[all.size() % 4],
                  {},
                  {},
                  {},
                  SeriesKind::Other};
    series.x = rung.corner->radius;
    series.y = rung.corner->mean_rate;
    series.converged.assign(series.x.size(), rung.converged());
    all.push_back(std::move(series));
  }
  if (all.empty()) {
    Axes(graph_area(), Axis{}, Axis{}).draw(canvas, false);
    draw_no_data(canvas, graph_area(), "no corner profile");
    return;
  }
  const Axes axes(graph_area(), range_axis(all, true, true, "distance ρ from the die corner"),
                  range_axis(all, false, true, "annulus mean of ε̄̇"));
  axes.draw(canvas, true);
  std::vector<LegendEntry> legend;
  canvas.clip(axes.area());
  for (const Series& series : all) {
    std::vector<Pixel> points;
    for (std::size_t k = 0; k < series.x.size(); ++k)
      points.push_back(axes.at(series.x[k], series.y[k]));
    canvas.polyline(points, {2.0, series.colour});
    for (std::size_t k = 0; k < points.size(); ++k)
      canvas.circle(points[k], 2.6, series.converged[k] ? series.colour : failed_colour);
    legend.push_back({series.label, {2.0, series.colour}});
  }
  // C/ρ through the outermost point of the finest rung, where every mesh agrees.
  const Series& finest = all.back();
  const double c = finest.x.back() * finest.y.back();
  const double x0 = axes.x_axis().lo, x1 = axes.x_axis().hi;
  canvas.line(axes.at(x0, c / x0), axes.at(x1, c / x1), {1.4, slope_colour, 1.0, 8.0});
  canvas.unclip();
  legend.push_back({"reference C/ρ (slope −1)", {1.4, slope_colour, 1.0, 8.0}});
  draw_legend(canvas, {axes.area().right() - 10, axes.area().y + 10}, legend);
}

Picture render_corner_plot(const post::StudyTable& table) {
  auto draw = [&table](Canvas& canvas) { draw_corner(canvas, table); };
  return Picture{"corner", render_png(picture_width, picture_height, draw),
                 render_svg(picture_width, picture_height, draw)};
}

Picture render_study_plot(const post::StudyTable& table) {
  auto draw = [&table](Canvas& canvas) { draw_study(canvas, table); };
  return Picture{"study", render_png(picture_width, picture_height, draw),
                 render_svg(picture_width, picture_height, draw)};
}

} // namespace formflow::io::plot
