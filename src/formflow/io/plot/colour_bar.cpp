// SPDX-License-Identifier: MIT
// The vertical colour bar of filled-contour pictures.
#include "formflow/io/plot/axes.hpp"
#include "formflow/io/plot/ticks.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace formflow::io::plot {

namespace {

/// Labelled values: decades on a log bar spanning ≥ 2 of them, otherwise the
/// band boundaries, thinned to every other one when they would crowd.
std::vector<double> colour_bar_ticks(const ColourScale& scale) {
  const std::vector<double>& bounds = scale.boundaries();
  if (scale.is_log()) {
    std::vector<double> decades = decade_ticks(bounds.front(), bounds.back());
    if (decades.size() >= 2) return decades;
    return bounds;
  }
  if (bounds.size() <= 12) return bounds;
  // Keep the parity that contains zero, so the white centre of a diverging bar is labelled.
  std::size_t parity = 0;
  for (std::size_t i = 0; i < bounds.size(); ++i)
    if (bounds[i] == 0.0) parity = i % 2;
  std::vector<double> ticks;
  for (std::size_t i = parity; i < bounds.size(); i += 2) ticks.push_back(bounds[i]);
  return ticks;
}

std::string colour_bar_label(const ColourScale& scale, double value) {
  const std::vector<double>& bounds = scale.boundaries();
  if (scale.is_log())
    return log_tick_label(value, log_labels_as_powers(bounds.front(), bounds.back()));
  return tick_label(value, bounds[1] - bounds[0]);
}

/// A triangle beyond one end of the bar in the end band's colour: "values go further".
void draw_extension(const Canvas& canvas, const Rect& bar, bool at_top, const Rgb& colour) {
  const double base = at_top ? bar.y : bar.bottom();
  const double tip = at_top ? bar.y - 14.0 : bar.bottom() + 14.0;
  const std::array<Pixel, 3> triangle = {
      {{bar.x, base}, {bar.right(), base}, {bar.x + 0.5 * bar.width, tip}}};
  canvas.fill(triangle, colour);
  canvas.polyline(triangle, {1.0, {0.15, 0.15, 0.15}}, true);
}

} // namespace

void draw_colour_bar(const Canvas& canvas, const Rect& bar, const ColourScale& scale,
                     std::string_view title) {
  const std::vector<double>& bounds = scale.boundaries();
  const double d0 = scale.display(bounds.front()), d1 = scale.display(bounds.back());
  auto y_of = [&](double value) {
    return bar.bottom() - (scale.display(value) - d0) / (d1 - d0) * bar.height;
  };
  for (std::size_t band = 0; band < scale.n_bands(); ++band) {
    const double top = y_of(bounds[band + 1]), bottom = y_of(bounds[band]);
    canvas.fill_rect({bar.x, top, bar.width, bottom - top + 0.5}, scale.band_colour(band));
  }
  // On pixel centres, so the 1 px frame is sharp rather than two grey columns.
  canvas.stroke_rect({std::floor(bar.x) + 0.5, std::floor(bar.y) + 0.5, std::round(bar.width),
                      std::round(bar.height)},
                     {1.0, {0.15, 0.15, 0.15}});
  if (scale.extends_below) draw_extension(canvas, bar, false, scale.band_colour(0));
  if (scale.extends_above)
    draw_extension(canvas, bar, true, scale.band_colour(scale.n_bands() - 1));

  const Font font{11.5};
  double widest = 0.0;
  for (const double tick : colour_bar_ticks(scale)) {
    const double y = y_of(tick);
    canvas.line({bar.right(), y}, {bar.right() + 4, y}, {1.0, {0.15, 0.15, 0.15}});
    const std::string label = colour_bar_label(scale, tick);
    canvas.text({bar.right() + 7, y}, label, font, HAlign::Left, VAlign::Middle);
    widest = std::max(widest, canvas.text_width(label, font));
  }
  canvas.text({bar.right() + 14 + widest, bar.y + 0.5 * bar.height}, title, Font{13.0},
              HAlign::Centre, VAlign::Top, 90.0);
}

} // namespace formflow::io::plot
