// SPDX-License-Identifier: MIT
// Axes, colour bar, legend and title drawing shared by every picture.
#include "formflow/io/plot/axes.hpp"

#include "formflow/io/plot/ticks.hpp"

#include <algorithm>
#include <cmath>

namespace formflow::io::plot {

namespace {

const Font tick_font{11.5};
const Font label_font{13.0};
const Stroke frame_stroke{1.0, {0.15, 0.15, 0.15}};
const Stroke grid_stroke{1.0, {0.85, 0.85, 0.85}};

void complete(Axis& axis) {
  if (axis.log) {
    if (!(axis.lo > 0)) axis.lo = axis.hi > 0 ? axis.hi * 1e-3 : 1e-3;
    if (!(axis.hi > axis.lo)) axis.hi = axis.lo * 10.0;
  } else if (!(axis.hi > axis.lo)) {
    const double half = std::max(std::abs(axis.lo) * 0.1, 1.0);
    axis.lo -= half;
    axis.hi += half;
  }
  if (!axis.ticks.empty()) return;
  if (!axis.log) {
    axis.ticks = linear_ticks(axis.lo, axis.hi, 6);
    return;
  }
  axis.ticks = decade_ticks(axis.lo, axis.hi);
  // Less than two decades: label the 1-2-5 values instead, or the axis reads as unlabelled.
  if (axis.ticks.size() < 2)
    for (const double level : log_125_levels(axis.lo, axis.hi))
      if (level >= axis.lo * (1 - 1e-9) && level <= axis.hi * (1 + 1e-9) &&
          std::find(axis.ticks.begin(), axis.ticks.end(), level) == axis.ticks.end())
        axis.ticks.push_back(level);
  std::sort(axis.ticks.begin(), axis.ticks.end());
}

/// The centre of the pixel containing `v`: a 1 px line there covers one pixel
/// column exactly instead of smearing grey over two.
double crisp(double v) {
  return std::floor(v) + 0.5;
}

double fraction(const Axis& axis, double value) {
  if (axis.log)
    return (std::log10(std::max(value, 1e-300)) - std::log10(axis.lo)) /
           (std::log10(axis.hi) - std::log10(axis.lo));
  return (value - axis.lo) / (axis.hi - axis.lo);
}

std::string label_of(const Axis& axis, double value) {
  if (axis.log) return log_tick_label(value, log_labels_as_powers(axis.lo, axis.hi));
  const double step = axis.ticks.size() > 1 ? axis.ticks[1] - axis.ticks[0] : std::abs(value);
  return tick_label(value, step > 0 ? step : 1.0);
}

/// Unlabelled 2…9 × 10^k ticks between the decades of a log axis.
std::vector<double> minor_log_ticks(const Axis& axis) {
  std::vector<double> ticks;
  for (int k = static_cast<int>(std::floor(std::log10(axis.lo)));
       k <= static_cast<int>(std::ceil(std::log10(axis.hi))); ++k)
    for (int m = 2; m <= 9; ++m) {
      const double value = m * std::pow(10.0, k);
      if (value > axis.lo && value < axis.hi) ticks.push_back(value);
    }
  return ticks;
}

double widest_label(const Canvas& canvas, const Axis& axis) {
  double widest = 0.0;
  for (const double tick : axis.ticks)
    widest = std::max(widest, canvas.text_width(label_of(axis, tick), tick_font));
  return widest;
}

} // namespace

Axes::Axes(const Rect& area, Axis x, Axis y) : area_(area), x_(std::move(x)), y_(std::move(y)) {
  complete(x_);
  complete(y_);
}

double Axes::px(double x) const {
  return area_.x + fraction(x_, x) * area_.width;
}
double Axes::py(double y) const {
  return area_.bottom() - fraction(y_, y) * area_.height;
}

void Axes::draw(const Canvas& canvas, bool grid) const {
  if (grid) {
    for (const double tick : x_.ticks)
      canvas.line({crisp(px(tick)), area_.y}, {crisp(px(tick)), area_.bottom()}, grid_stroke);
    for (const double tick : y_.ticks)
      canvas.line({area_.x, crisp(py(tick))}, {area_.right(), crisp(py(tick))}, grid_stroke);
  }
  const Rect frame{crisp(area_.x), crisp(area_.y), std::round(area_.width),
                   std::round(area_.height)};
  canvas.stroke_rect(frame, frame_stroke);
  draw_x_ticks(canvas, frame.bottom());
  draw_y_ticks(canvas, frame.x);
}

void Axes::draw_spines(const Canvas& canvas, double offset) const {
  const double x = crisp(area_.x - offset), y = crisp(area_.bottom() + offset);
  canvas.line({area_.x, y}, {area_.right(), y}, frame_stroke);
  canvas.line({x, area_.y}, {x, area_.bottom()}, frame_stroke);
  draw_x_ticks(canvas, y);
  draw_y_ticks(canvas, x);
}

void Axes::draw_x_ticks(const Canvas& canvas, double y) const {
  for (const double tick : x_.ticks) {
    canvas.line({crisp(px(tick)), y}, {crisp(px(tick)), y + 5}, frame_stroke);
    canvas.text({px(tick), y + 8}, label_of(x_, tick), tick_font, HAlign::Centre, VAlign::Top);
  }
  canvas.text({area_.x + 0.5 * area_.width, y + 28}, x_.label, label_font, HAlign::Centre,
              VAlign::Top);
}

void Axes::draw_y_ticks(const Canvas& canvas, double x) const {
  for (const double tick : y_.ticks) {
    canvas.line({x - 5, crisp(py(tick))}, {x, crisp(py(tick))}, frame_stroke);
    canvas.text({x - 8, py(tick)}, label_of(y_, tick), tick_font, HAlign::Right, VAlign::Middle);
  }
  if (y_.log)
    for (const double tick : minor_log_ticks(y_))
      canvas.line({x - 3, crisp(py(tick))}, {x, crisp(py(tick))}, frame_stroke);
  const double label_x = x - 14 - widest_label(canvas, y_);
  canvas.text({label_x, area_.y + 0.5 * area_.height}, y_.label, label_font, HAlign::Centre,
              VAlign::Bottom, 90.0);
}

void Axes::draw_right(const Canvas& canvas, const Rgb& colour) const {
  const Stroke stroke{1.0, colour};
  Font font = tick_font;
  font.colour = colour;
  for (const double tick : y_.ticks) {
    canvas.line({crisp(area_.right()), crisp(py(tick))}, {area_.right() + 5, crisp(py(tick))},
                stroke);
    canvas.text({area_.right() + 8, py(tick)}, label_of(y_, tick), font, HAlign::Left,
                VAlign::Middle);
  }
  Font label = label_font;
  label.colour = colour;
  const double label_x = area_.right() + 14 + widest_label(canvas, y_);
  canvas.text({label_x, area_.y + 0.5 * area_.height}, y_.label, label, HAlign::Centre, VAlign::Top,
              90.0);
}

Axes equal_aspect_axes(const Rect& area, double x0, double x1, double y0, double y1) {
  const double scale = std::min(area.width / (x1 - x0), area.height / (y1 - y0));
  const double width = scale * (x1 - x0), height = scale * (y1 - y0);
  const Rect fitted{area.x + 0.5 * (area.width - width), area.y + 0.5 * (area.height - height),
                    width, height};
  return Axes(fitted, Axis{x0, x1, false, {}, "x"}, Axis{y0, y1, false, {}, "y"});
}

void draw_legend(const Canvas& canvas, Pixel corner, std::span<const LegendEntry> entries,
                 HAlign side) {
  if (entries.empty()) return;
  const double row = 20.0, sample = 30.0, pad = 8.0;
  double widest = 0.0;
  for (const auto& entry : entries)
    widest = std::max(widest, canvas.text_width(entry.label, tick_font));
  const double width = 2 * pad + sample + 8 + widest;
  const Rect box{side == HAlign::Left ? corner[0] : corner[0] - width, corner[1], width,
                 2 * pad + row * static_cast<double>(entries.size()) - 4};
  canvas.fill_rect(box, {1, 1, 1}, 0.9);
  canvas.stroke_rect({crisp(box.x), crisp(box.y), std::round(box.width), std::round(box.height)},
                     {1.0, {0.7, 0.7, 0.7}});
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double y = box.y + pad + row * (static_cast<double>(i) + 0.5) - 2;
    canvas.line({box.x + pad, y}, {box.x + pad + sample, y}, entries[i].stroke);
    canvas.text({box.x + pad + sample + 8, y}, entries[i].label, tick_font, HAlign::Left,
                VAlign::Middle);
  }
}

void draw_title(const Canvas& canvas, std::string_view title, std::string_view subtitle) {
  canvas.text({0.5 * canvas.width(), 12}, title, Font{17.0, true}, HAlign::Centre, VAlign::Top);
  canvas.text({0.5 * canvas.width(), 38}, subtitle, Font{12.0, false, {0.35, 0.35, 0.35}},
              HAlign::Centre, VAlign::Top);
}

void draw_no_data(const Canvas& canvas, const Rect& area, std::string_view what) {
  canvas.text({area.x + 0.5 * area.width, area.y + 0.5 * area.height}, what,
              Font{15.0, false, {0.5, 0.5, 0.5}}, HAlign::Centre, VAlign::Middle);
}

} // namespace formflow::io::plot
