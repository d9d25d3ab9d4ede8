// SPDX-License-Identifier: MIT
// Tick positions and compact labels for linear and logarithmic axes.
#include "formflow/io/plot/ticks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace formflow::io::plot {

namespace {

std::string superscript_integer(int value) {
  static constexpr std::array<const char*, 10> digits = {"⁰", "¹", "²", "³", "⁴",
                                                         "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = value < 0 ? "⁻" : "";
  for (const char c : std::to_string(std::abs(value))) out += digits[c - '0'];
  return out;
}

/// Typographic minus: "-" looks like a hyphen next to digits.
std::string with_minus_sign(std::string text) {
  if (!text.empty() && text[0] == '-') text.replace(0, 1, "−");
  return text;
}

} // namespace

double nice_step(double span, int target) {
  if (!(span > 0) || !std::isfinite(span)) return 1.0;
  const double raw = span / std::max(target, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double fraction = raw / magnitude;
  const double nice = fraction < 1.5 ? 1.0 : fraction < 3.5 ? 2.0 : fraction < 7.5 ? 5.0 : 10.0;
  return nice * magnitude;
}

std::vector<double> linear_ticks(double lo, double hi, int target) {
  const double step = nice_step(hi - lo, target);
  std::vector<double> ticks;
  const double tolerance = 1e-9 * step;
  for (double tick = std::ceil((lo - tolerance) / step) * step; tick <= hi + tolerance;
       tick += step)
    ticks.push_back(std::abs(tick) < tolerance ? 0.0 : tick);
  return ticks;
}

std::vector<double> decade_ticks(double lo, double hi) {
  std::vector<double> ticks;
  if (!(lo > 0) || !(hi >= lo)) return ticks;
  for (int k = static_cast<int>(std::ceil(std::log10(lo) - 1e-9));
       k <= static_cast<int>(std::floor(std::log10(hi) + 1e-9)); ++k)
    ticks.push_back(std::pow(10.0, k));
  return ticks;
}

std::vector<double> log_125_levels(double lo, double hi) {
  std::vector<double> levels;
  const int first_decade = static_cast<int>(std::floor(std::log10(lo))) - 1;
  for (int k = first_decade; levels.empty() || levels.back() < hi * (1 - 1e-12); ++k)
    for (const double mantissa : {1.0, 2.0, 5.0}) {
      const double level = mantissa * std::pow(10.0, k);
      if (level <= lo * (1 + 1e-12))
        levels.assign(1, level); // largest one ≤ lo so far
      else if (levels.empty() || levels.back() < hi * (1 - 1e-12))
        levels.push_back(level);
    }
  return levels;
}

std::string tick_label(double value, double step) {
  if (value == 0.0) return "0";
  const double magnitude = std::max(std::abs(value), std::abs(step));
  if (magnitude >= 1e5 || magnitude < 1e-4) {
    const int exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
    const double mantissa = value / std::pow(10.0, exponent);
    std::string head = std::abs(mantissa - 1.0) < 1e-9 ? "" : fmt::format("{:.3g}×", mantissa);
    return with_minus_sign(head + "10" + superscript_integer(exponent));
  }
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  return with_minus_sign(fmt::format("{:.{}f}", value, decimals));
}

bool log_labels_as_powers(double lo, double hi) {
  return lo < 0.999e-3 || hi > 1.001e4;
}

std::string log_tick_label(double value, bool powers) {
  const int exponent = static_cast<int>(std::lround(std::log10(value)));
  if (std::abs(value - std::pow(10.0, exponent)) > 1e-9 * value)
    return with_minus_sign(fmt::format("{:.3g}", value));
  if (!powers) return fmt::format("{:.{}f}", value, std::max(0, -exponent));
  return "10" + superscript_integer(exponent);
}

} // namespace formflow::io::plot
