// SPDX-License-Identifier: MIT
// Canvas primitives, the small text markup, and PNG/SVG rendering through cairo.
#include "formflow/io/plot/canvas.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace formflow::io::plot {

namespace {

/// A piece of text at one script level: 0 normal, −1 subscript, +1 superscript.
/// A run carrying a mark holds exactly one base character.
struct Run {
  std::string text;
  int level = 0;
  bool macron = false;
  bool dot = false;
};

constexpr char32_t combining_macron = 0x0304;
constexpr char32_t combining_dot_above = 0x0307;

/// Length of the UTF-8 sequence starting with `lead` (1 for stray bytes).
std::size_t utf8_length(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

char32_t decode_two_or_three(std::string_view bytes) {
  if (bytes.size() == 2) return ((bytes[0] & 0x1F) << 6) | (bytes[1] & 0x3F);
  if (bytes.size() == 3)
    return ((bytes[0] & 0x0F) << 12) | ((bytes[1] & 0x3F) << 6) | (bytes[2] & 0x3F);
  return 0;
}

std::vector<Run> parse_markup(std::string_view markup) {
  std::vector<Run> runs;
  std::vector<int> levels{0};
  for (std::size_t i = 0; i < markup.size();) {
    const char c = markup[i];
    if ((c == '_' || c == '^') && i + 1 < markup.size() && markup[i + 1] == '{') {
      levels.push_back(c == '_' ? -1 : 1);
      i += 2;
      continue;
    }
    if (c == '}' && levels.size() > 1) {
      levels.pop_back();
      ++i;
      continue;
    }
    const std::size_t length =
        std::min(utf8_length(static_cast<unsigned char>(c)), markup.size() - i);
    const std::string_view character = markup.substr(i, length);
    i += length;
    const char32_t code = decode_two_or_three(character);
    if ((code == combining_macron || code == combining_dot_above) && !runs.empty()) {
      Run& base = runs.back();
      // Split the mark's base character off the end of its run.
      if (!base.macron && !base.dot && base.text.size() > 1) {
        std::size_t start = base.text.size() - 1;
        while (start > 0 && (static_cast<unsigned char>(base.text[start]) & 0xC0) == 0x80) --start;
        runs.push_back({base.text.substr(start), base.level});
        runs[runs.size() - 2].text.resize(start);
      }
      (code == combining_macron ? runs.back().macron : runs.back().dot) = true;
      continue;
    }
    if (runs.empty() || runs.back().level != levels.back() || runs.back().macron || runs.back().dot)
      runs.push_back({std::string(), levels.back()});
    runs.back().text += character;
  }
  return runs;
}

double run_size(const Run& run, double size) {
  return run.level == 0 ? size : 0.7 * size;
}

void select_font(cairo_t* cairo, const Font& font, double size) {
  cairo_select_font_face(cairo, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         font.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo, size);
}

double markup_width(cairo_t* cairo, const std::vector<Run>& runs, const Font& font) {
  double width = 0.0;
  for (const Run& run : runs) {
    select_font(cairo, font, run_size(run, font.size));
    cairo_text_extents_t extents;
    cairo_text_extents(cairo, run.text.c_str(), &extents);
    width += extents.x_advance;
  }
  return width;
}

/// Macron and dot above the ink of the glyph just drawn at (x, baseline).
void draw_marks(cairo_t* cairo, const Run& run, double x, double baseline, double size) {
  cairo_text_extents_t ink;
  cairo_text_extents(cairo, run.text.c_str(), &ink);
  double top = baseline + ink.y_bearing - 0.12 * size;
  const double left = x + ink.x_bearing, right = left + ink.width;
  if (run.macron) {
    cairo_set_line_width(cairo, 0.075 * size);
    cairo_move_to(cairo, left, top);
    cairo_line_to(cairo, right + 0.05 * size, top);
    cairo_stroke(cairo);
    top -= 0.17 * size;
  }
  if (run.dot) {
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, 0.5 * (left + right) + 0.03 * size, top, 0.065 * size, 0.0,
              2.0 * std::numbers::pi);
    cairo_fill(cairo);
  }
}

struct CairoDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
  void operator()(cairo_t* cairo) const { cairo_destroy(cairo); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, CairoDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, CairoDeleter>;

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void check(cairo_status_t status, const char* what) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo: ") + what + ": " + cairo_status_to_string(status));
}

/// White background, then the picture.
void draw_on(cairo_surface_t* surface, int width, int height, const DrawFunction& draw) {
  ContextPtr cairo(cairo_create(surface));
  check(cairo_status(cairo.get()), "cannot create a context");
  cairo_set_source_rgb(cairo.get(), 1.0, 1.0, 1.0);
  cairo_paint(cairo.get());
  Canvas canvas(cairo.get(), width, height);
  draw(canvas);
  check(cairo_status(cairo.get()), "drawing failed");
}

} // namespace

double Canvas::text_width(std::string_view markup, const Font& font) const {
  cairo_save(cairo_);
  const double width = markup_width(cairo_, parse_markup(markup), font);
  cairo_restore(cairo_);
  return width;
}

void Canvas::text(Pixel at, std::string_view markup, const Font& font, HAlign h, VAlign v,
                  double angle_deg) const {
  const std::vector<Run> runs = parse_markup(markup);
  cairo_save(cairo_);
  cairo_translate(cairo_, at[0], at[1]);
  cairo_rotate(cairo_, -angle_deg * std::numbers::pi / 180.0);
  const double width = markup_width(cairo_, runs, font);
  select_font(cairo_, font, font.size);
  cairo_font_extents_t metrics;
  cairo_font_extents(cairo_, &metrics);
  double x = h == HAlign::Left ? 0.0 : h == HAlign::Centre ? -0.5 * width : -width;
  const double baseline = v == VAlign::Top      ? metrics.ascent
                          : v == VAlign::Middle ? 0.5 * (metrics.ascent - metrics.descent)
                          : v == VAlign::Bottom ? -metrics.descent
                                                : 0.0;
  cairo_set_source_rgb(cairo_, font.colour.r, font.colour.g, font.colour.b);
  for (const Run& run : runs) {
    const double size = run_size(run, font.size);
    const double shift = run.level < 0 ? 0.25 * font.size : run.level > 0 ? -0.4 * font.size : 0.0;
    select_font(cairo_, font, size);
    cairo_move_to(cairo_, x, baseline + shift);
    cairo_show_text(cairo_, run.text.c_str());
    if (run.macron || run.dot) draw_marks(cairo_, run, x, baseline + shift, size);
    cairo_text_extents_t extents;
    cairo_text_extents(cairo_, run.text.c_str(), &extents);
    x += extents.x_advance;
  }
  cairo_restore(cairo_);
}

void Canvas::apply(const Stroke& stroke) const {
  cairo_set_source_rgba(cairo_, stroke.colour.r, stroke.colour.g, stroke.colour.b, stroke.alpha);
  cairo_set_line_width(cairo_, stroke.width);
  cairo_set_line_join(cairo_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cairo_, stroke.dash > 0 ? CAIRO_LINE_CAP_BUTT : CAIRO_LINE_CAP_ROUND);
  const double dash[] = {stroke.dash, 0.6 * stroke.dash};
  cairo_set_dash(cairo_, dash, stroke.dash > 0 ? 2 : 0, 0.0);
}

void Canvas::line(Pixel from, Pixel to, const Stroke& stroke) const {
  const std::array<Pixel, 2> points = {from, to};
  polyline(points, stroke);
}

void Canvas::polyline(std::span<const Pixel> points, const Stroke& stroke, bool closed) const {
  if (points.size() < 2) return;
  cairo_new_path(cairo_);
  cairo_move_to(cairo_, points[0][0], points[0][1]);
  for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cairo_, points[i][0], points[i][1]);
  if (closed) cairo_close_path(cairo_);
  apply(stroke);
  cairo_stroke(cairo_);
}

void Canvas::fill(std::span<const Pixel> polygon, const Rgb& colour, double alpha,
                  bool seal) const {
  if (polygon.size() < 3) return;
  cairo_new_path(cairo_);
  cairo_move_to(cairo_, polygon[0][0], polygon[0][1]);
  for (std::size_t i = 1; i < polygon.size(); ++i)
    cairo_line_to(cairo_, polygon[i][0], polygon[i][1]);
  cairo_close_path(cairo_);
  cairo_set_source_rgba(cairo_, colour.r, colour.g, colour.b, alpha);
  if (!seal) {
    cairo_fill(cairo_);
    return;
  }
  cairo_fill_preserve(cairo_);
  apply({0.6, colour, alpha});
  cairo_stroke(cairo_);
}

void Canvas::fill_polygons(std::span<const std::vector<Pixel>> polygons, const Rgb& colour,
                           bool seal) const {
  cairo_new_path(cairo_);
  for (const auto& polygon : polygons) {
    if (polygon.size() < 3) continue;
    cairo_move_to(cairo_, polygon[0][0], polygon[0][1]);
    for (std::size_t i = 1; i < polygon.size(); ++i)
      cairo_line_to(cairo_, polygon[i][0], polygon[i][1]);
    cairo_close_path(cairo_);
  }
  cairo_set_source_rgb(cairo_, colour.r, colour.g, colour.b);
  if (!seal) {
    cairo_fill(cairo_);
    return;
  }
  cairo_fill_preserve(cairo_);
  apply({0.6, colour});
  cairo_stroke(cairo_);
}

void Canvas::fill_rect(const Rect& rect, const Rgb& colour, double alpha) const {
  cairo_new_path(cairo_);
  cairo_rectangle(cairo_, rect.x, rect.y, rect.width, rect.height);
  cairo_set_source_rgba(cairo_, colour.r, colour.g, colour.b, alpha);
  cairo_fill(cairo_);
}

void Canvas::stroke_rect(const Rect& rect, const Stroke& stroke) const {
  cairo_new_path(cairo_);
  cairo_rectangle(cairo_, rect.x, rect.y, rect.width, rect.height);
  apply(stroke);
  cairo_stroke(cairo_);
}

void Canvas::circle(Pixel centre, double radius, const Rgb& colour) const {
  cairo_new_path(cairo_);
  cairo_arc(cairo_, centre[0], centre[1], radius, 0.0, 2.0 * std::numbers::pi);
  cairo_set_source_rgb(cairo_, colour.r, colour.g, colour.b);
  cairo_fill(cairo_);
}

void Canvas::clip(const Rect& rect) const {
  cairo_save(cairo_);
  cairo_new_path(cairo_);
  cairo_rectangle(cairo_, rect.x, rect.y, rect.width, rect.height);
  cairo_clip(cairo_);
}

void Canvas::unclip() const {
  cairo_restore(cairo_);
}

std::string render_png(int width, int height, const DrawFunction& draw) {
  // RGB24: an opaque picture needs no alpha channel, and the file is smaller.
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  check(cairo_surface_status(surface.get()), "cannot create an image");
  draw_on(surface.get(), width, height, draw);
  std::string bytes;
  check(cairo_surface_write_to_png_stream(surface.get(), append_bytes, &bytes), "PNG encoding");
  return bytes;
}

std::string render_svg(int width, int height, const DrawFunction& draw) {
  std::string text;
  {
    SurfacePtr surface(cairo_svg_surface_create_for_stream(append_bytes, &text, width, height));
    check(cairo_surface_status(surface.get()), "cannot create an SVG surface");
    // Pixels, so the SVG opens at the same size as the PNG (cairo's default is points).
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
    draw_on(surface.get(), width, height, draw);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), "SVG output");
  }
  return text;
}

} // namespace formflow::io::plot
