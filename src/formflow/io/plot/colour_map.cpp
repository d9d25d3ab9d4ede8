// SPDX-License-Identifier: MIT
// Colour maps by piecewise-linear interpolation of published control points.
#include "formflow/io/plot/colour_map.hpp"

#include "formflow/core/error.hpp"
#include "formflow/io/plot/ticks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace formflow::io::plot {

namespace {

/// Interpolates equally spaced control points at t ∈ [0, 1].
Rgb interpolate(std::span<const Rgb> points, double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  const double position = t * static_cast<double>(points.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(position), points.size() - 2);
  const double w = position - static_cast<double>(i);
  const Rgb& a = points[i];
  const Rgb& b = points[i + 1];
  return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b)};
}

// viridis (van der Walt & Smith, CC0) sampled at t = 0, 0.1, ..., 1.
constexpr std::array<Rgb, 11> viridis_points = {{{0.267004, 0.004874, 0.329415},
                                                 {0.282623, 0.140926, 0.457517},
                                                 {0.253935, 0.265254, 0.529983},
                                                 {0.206756, 0.371758, 0.553117},
                                                 {0.163625, 0.471133, 0.558148},
                                                 {0.127568, 0.566949, 0.550556},
                                                 {0.134692, 0.658636, 0.517649},
                                                 {0.266941, 0.748751, 0.440573},
                                                 {0.477504, 0.821444, 0.318195},
                                                 {0.741388, 0.873449, 0.149561},
                                                 {0.993248, 0.906157, 0.143936}}};

constexpr Rgb hex(unsigned value) {
  return {((value >> 16) & 0xff) / 255.0, ((value >> 8) & 0xff) / 255.0, (value & 0xff) / 255.0};
}

// ColorBrewer RdBu (11 classes), blue end first.
constexpr std::array<Rgb, 11> blue_white_red_points = {
    {hex(0x053061), hex(0x2166ac), hex(0x4393c3), hex(0x92c5de), hex(0xd1e5f0), hex(0xf7f7f7),
     hex(0xfddbc7), hex(0xf4a582), hex(0xd6604d), hex(0xb2182b), hex(0x67001f)}};

/// Values this small are "zero" on a log scale (ε̄̇ of a rigid zone).
constexpr double log_floor = 1e-300;

} // namespace

Rgb viridis(double t) {
  return interpolate(viridis_points, t);
}
Rgb blue_white_red(double t) {
  return interpolate(blue_white_red_points, t);
}

ColourScale ColourScale::logarithmic(double lo, double hi) {
  if (!(lo > 0 && hi > lo && std::isfinite(hi)))
    throw InternalError("plot: logarithmic colour scale needs 0 < lo < hi");
  ColourScale scale;
  scale.log_ = true;
  scale.boundaries_ = log_125_levels(lo, hi);
  return scale;
}

ColourScale ColourScale::linear(double lo, double hi, int target_bands, Palette palette) {
  if (!(std::isfinite(lo) && std::isfinite(hi)))
    throw InternalError("plot: linear colour scale needs a finite range");
  // A constant field (or one constant to round-off: a step below the values' resolution
  // would never advance the loop below) still gets one visible band around its value.
  if (!(hi - lo > 1e-9 * std::max(std::abs(lo), std::abs(hi)))) {
    const double half = std::max(std::abs(lo) * 0.05, 1e-12);
    lo -= half;
    hi += half;
  }
  ColourScale scale;
  scale.palette_ = palette;
  const double step = nice_step(hi - lo, target_bands);
  for (double level = std::floor(lo / step) * step; level < hi + 0.5 * step; level += step)
    scale.boundaries_.push_back(std::abs(level) < 1e-9 * step ? 0.0 : level);
  if (scale.boundaries_.back() < hi) scale.boundaries_.push_back(scale.boundaries_.back() + step);
  if (scale.boundaries_.size() < 2) scale.boundaries_.push_back(scale.boundaries_.back() + step);
  return scale;
}

double ColourScale::display(double value) const {
  return log_ ? std::log10(std::max(value, log_floor)) : value;
}

Rgb ColourScale::band_colour(std::size_t band) const {
  const double lo = boundaries_[band], hi = boundaries_[band + 1];
  if (palette_ == Palette::Diverging) {
    const double extent = std::max(std::abs(boundaries_.front()), std::abs(boundaries_.back()));
    return blue_white_red(0.5 + 0.5 * (0.5 * (lo + hi)) / extent);
  }
  // Sequential bands sample the map at their centres so the end bands are not the extremes.
  const double t = (static_cast<double>(band) + 0.5) / static_cast<double>(n_bands());
  return viridis(palette_ == Palette::SequentialDark ? 0.8 * t : t);
}

std::size_t ColourScale::band_of(double value) const {
  const auto above = std::upper_bound(boundaries_.begin() + 1, boundaries_.end() - 1, value);
  return static_cast<std::size_t>(above - boundaries_.begin()) - 1;
}

} // namespace formflow::io::plot
