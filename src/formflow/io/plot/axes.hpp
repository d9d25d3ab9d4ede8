// SPDX-License-Identifier: MIT
// Plot frames: data-to-pixel mapping, ticks and labels, colour bar, legend, titles.
#pragma once

#include "formflow/io/plot/canvas.hpp"
#include "formflow/io/plot/colour_map.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace formflow::io::plot {

/// One axis: data range, scale, tick positions (empty: chosen automatically) and label markup.
struct Axis {
  double lo = 0.0, hi = 1.0;
  bool log = false; ///< logarithmic (lo > 0)
  std::vector<double> ticks;
  std::string label;
};

/// A rectangular plot area with an x and a y axis.
class Axes {
public:
  /// Fills empty tick lists; widens an empty range so the mapping stays finite.
  Axes(const Rect& area, Axis x, Axis y);

  const Rect& area() const { return area_; }
  const Axis& x_axis() const { return x_; }
  const Axis& y_axis() const { return y_; }
  double px(double x) const;
  double py(double y) const;
  Pixel at(double x, double y) const { return {px(x), py(y)}; }

  /// Frame, ticks and tick labels (left and bottom), axis labels; optional light grid.
  void draw(const Canvas& canvas, bool grid) const;
  /// Only a left and a bottom axis line, `offset` pixels outside the area, with
  /// ticks and labels: for mesh pictures, where a full frame would read as
  /// part of the domain boundary.
  void draw_spines(const Canvas& canvas, double offset) const;
  /// The y axis drawn on the right edge instead (a second quantity over the same x).
  void draw_right(const Canvas& canvas, const Rgb& colour) const;

private:
  void draw_x_ticks(const Canvas& canvas, double y) const;
  void draw_y_ticks(const Canvas& canvas, double x) const;
  Rect area_;
  Axis x_, y_;
};

/// Axes over the data box [x0, x1] × [y0, y1] with one data unit the same
/// length in x and y, as large as fits in `area` and centred in it.
Axes equal_aspect_axes(const Rect& area, double x0, double x1, double y0, double y1);

/// A vertical colour bar in `bar` with ticks, labels and a rotated `title` to its right.
void draw_colour_bar(const Canvas& canvas, const Rect& bar, const ColourScale& scale,
                     std::string_view title);

/// One legend line: a sample of the stroke and its label.
struct LegendEntry {
  std::string label;
  Stroke stroke;
};

/// A boxed legend with its top-right (`side` Right) or top-left (Left) corner at `corner`.
void draw_legend(const Canvas& canvas, Pixel corner, std::span<const LegendEntry> entries,
                 HAlign side = HAlign::Right);

/// Picture title (bold, centred) and a smaller grey subtitle line under it.
void draw_title(const Canvas& canvas, std::string_view title, std::string_view subtitle);

/// A light-grey "no data" note in the middle of `area`.
void draw_no_data(const Canvas& canvas, const Rect& area, std::string_view what);

} // namespace formflow::io::plot
