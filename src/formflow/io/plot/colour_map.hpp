// SPDX-License-Identifier: MIT
// Colour maps and the discrete colour levels of filled-contour pictures.
#pragma once

#include <cstddef>
#include <vector>

namespace formflow::io::plot {

/// An opaque colour, each channel in [0, 1].
struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
};

/// Sequential, perceptually uniform (viridis): dark purple at 0, yellow at 1.
/// `t` is clamped to [0, 1].
Rgb viridis(double t);

/// Diverging blue – white – red (ColorBrewer RdBu, reversed): white at 0.5.
/// `t` is clamped to [0, 1].
Rgb blue_white_red(double t);

/// Which colour map a scale uses.
enum class Palette {
  Sequential,     ///< viridis, for filled areas
  SequentialDark, ///< viridis without its palest quarter, for lines and arrows on white
  Diverging,      ///< blue–white–red, white at zero
};

/// Filled-contour levels: band k covers [boundaries[k], boundaries[k+1]] and
/// has one colour. Values outside the first/last boundary are drawn in the end
/// colours; `extends_below`/`extends_above` say whether the data go there (the
/// colour bar then shows a triangle, as in engineering plots).
class ColourScale {
public:
  /// Log-spaced bands at 1-2-5 steps per decade covering [lo, hi], 0 < lo < hi; viridis.
  static ColourScale logarithmic(double lo, double hi);
  /// Linearly spaced bands at a "nice" step (about `target_bands` of them)
  /// covering [lo, hi]. Palette::Diverging puts white at zero with the same
  /// colour-per-unit on both sides.
  static ColourScale linear(double lo, double hi, int target_bands, Palette palette);

  /// Band boundaries in data units, strictly increasing, at least two.
  const std::vector<double>& boundaries() const { return boundaries_; }
  std::size_t n_bands() const { return boundaries_.size() - 1; }
  bool is_log() const { return log_; }
  /// The coordinate bands are linear in: log10(value) (clamped to a tiny positive) or value.
  double display(double value) const;
  /// Colour of band `band` (0 ≤ band < n_bands()).
  Rgb band_colour(std::size_t band) const;
  /// Band containing `value`, clamped to the end bands.
  std::size_t band_of(double value) const;

  bool extends_below = false; ///< some data lie below boundaries().front()
  bool extends_above = false; ///< some data lie above boundaries().back()

private:
  std::vector<double> boundaries_;
  bool log_ = false;
  Palette palette_ = Palette::Sequential;
};

} // namespace formflow::io::plot
