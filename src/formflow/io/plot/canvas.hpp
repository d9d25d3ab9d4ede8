// SPDX-License-Identifier: MIT
// A drawing surface over cairo with the few primitives the pictures need, and PNG/SVG rendering.
#pragma once

#include "formflow/io/plot/colour_map.hpp"

#include <array>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

using cairo_t = struct _cairo;

namespace formflow::io::plot {

/// A point in device units (pixels; y grows downwards).
using Pixel = std::array<double, 2>;

/// An axis-aligned rectangle in device units.
struct Rect {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
  double right() const { return x + width; }
  double bottom() const { return y + height; }
};

enum class HAlign { Left, Centre, Right };
enum class VAlign { Top, Middle, Baseline, Bottom };

/// Text style: size in pixels, weight, colour.
struct Font {
  double size = 13.0;
  bool bold = false;
  Rgb colour{0.1, 0.1, 0.1};
};

/// Line style: width in pixels, colour, opacity, optional dash length.
struct Stroke {
  double width = 1.0;
  Rgb colour{0.1, 0.1, 0.1};
  double alpha = 1.0;
  double dash = 0.0; ///< 0: solid; otherwise on/off length in pixels
};

/// Wraps a cairo context. Text takes a small markup: `_{…}` subscript,
/// `^{…}` superscript, and the combining macron (U+0304) and dot above
/// (U+0307) drawn by hand, because cairo's toy text API stacks them on top of
/// each other (ε̄̇ would lose its dot).
class Canvas {
public:
  Canvas(cairo_t* cairo, double width, double height)
      : cairo_(cairo), width_(width), height_(height) {}

  double width() const { return width_; }
  double height() const { return height_; }
  /// The underlying context, for the rare call these helpers do not cover.
  cairo_t* cairo() const { return cairo_; }

  /// Width of `markup` set in `font`, in pixels.
  double text_width(std::string_view markup, const Font& font) const;
  /// Draws `markup` anchored at `at`; `angle_deg` = 90 writes bottom-to-top.
  void text(Pixel at, std::string_view markup, const Font& font, HAlign h = HAlign::Left,
            VAlign v = VAlign::Baseline, double angle_deg = 0.0) const;

  void line(Pixel from, Pixel to, const Stroke& stroke) const;
  void polyline(std::span<const Pixel> points, const Stroke& stroke, bool closed = false) const;
  /// Fills a polygon; `seal` strokes its edge in the same colour, hiding the
  /// hairline seams anti-aliasing leaves between adjacent fills.
  void fill(std::span<const Pixel> polygon, const Rgb& colour, double alpha = 1.0,
            bool seal = false) const;
  /// Fills many polygons as one path (one SVG element, no seams between
  /// them); they must all have the same orientation.
  void fill_polygons(std::span<const std::vector<Pixel>> polygons, const Rgb& colour,
                     bool seal) const;
  void fill_rect(const Rect& rect, const Rgb& colour, double alpha = 1.0) const;
  void stroke_rect(const Rect& rect, const Stroke& stroke) const;
  void circle(Pixel centre, double radius, const Rgb& colour) const;
  /// Restricts drawing to `rect` until unclip().
  void clip(const Rect& rect) const;
  void unclip() const;

private:
  void apply(const Stroke& stroke) const;
  cairo_t* cairo_;
  double width_, height_;
};

/// A picture: draws itself on a canvas of the given size.
using DrawFunction = std::function<void(Canvas&)>;

/// Renders `draw` on a white `width`×`height` raster and returns the PNG file bytes.
/// Throws std::runtime_error if cairo fails.
std::string render_png(int width, int height, const DrawFunction& draw);
/// Renders `draw` as an SVG document of `width`×`height` px and returns its text.
std::string render_svg(int width, int height, const DrawFunction& draw);

} // namespace formflow::io::plot
