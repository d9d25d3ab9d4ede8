// SPDX-License-Identifier: MIT
// Axis tick positions and labels ("nice" 1-2-5 numbers).
#pragma once

#include <string>
#include <vector>

namespace formflow::io::plot {

/// The 1, 2 or 5 × 10^k step that splits `span` > 0 into about `target` intervals.
double nice_step(double span, int target);

/// Multiples of nice_step(hi − lo, target) inside [lo, hi] (with a little tolerance).
std::vector<double> linear_ticks(double lo, double hi, int target);

/// Powers of ten inside [lo, hi], 0 < lo ≤ hi.
std::vector<double> decade_ticks(double lo, double hi);

/// 1-2-5 × 10^k values from the largest one ≤ lo to the smallest one ≥ hi, 0 < lo < hi.
std::vector<double> log_125_levels(double lo, double hi);

/// A tick label with no more decimals than `step` needs ("2.5", "−1", "0.001");
/// Unicode minus, and "1.5×10⁴"-style mantissas for very large or small values.
std::string tick_label(double value, double step);

/// Whether a log axis over [lo, hi] labels its ticks as powers ("10⁻⁶"): when
/// plain decimals would get long (beyond 10⁻³ … 10⁴). One choice per axis, so
/// "0.01" and "10⁻⁵" never share an axis.
bool log_labels_as_powers(double lo, double hi);

/// A log-axis label: plain decimals ("0.001", "100") or powers of ten ("10⁻⁶");
/// values that are not powers of ten get three significant digits either way.
std::string log_tick_label(double value, bool powers);

} // namespace formflow::io::plot
