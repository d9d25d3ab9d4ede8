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

/// A log-axis label: plain decimals for 10⁻³ … 10⁴, else "10⁻⁶"-style powers.
std::string log_tick_label(double value);

}  // namespace formflow::io::plot
