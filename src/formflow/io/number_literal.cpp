// SPDX-License-Identifier: MIT
// Re-reading TOML number literals with std::from_chars, which reports out-of-range values.
#include "formflow/io/number_literal.hpp"

#include "formflow/core/printable_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <system_error>

namespace formflow::io {

std::optional<std::string> number_literal_problem(std::string_view literal, bool integer) {
  std::string digits;
  for (const char c : literal)
    if (c != '_') digits += c;
  if (!digits.empty() && digits.front() == '+') digits.erase(0, 1); // from_chars takes no '+'
  const char* first = digits.data();
  const char* last = digits.data() + digits.size();
  const std::string shown = printable_text(literal, 40);
  if (integer) {
    int base = 10;
    if (digits.size() > 2 && digits[0] == '0' &&
        (digits[1] == 'x' || digits[1] == 'o' || digits[1] == 'b')) {
      base = digits[1] == 'x' ? 16 : digits[1] == 'o' ? 8 : 2;
      first += 2;
    }
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(first, last, value, base);
    if (error == std::errc::result_out_of_range)
      return shown + " does not fit a 64-bit integer (|value| ≤ 9223372036854775807)";
    return std::nullopt;
  }
  if (digits.find_first_of("in") != std::string::npos) return std::nullopt; // inf, nan
  double value = 0;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc::result_out_of_range) return std::nullopt;
  // from_chars reports overflow and underflow alike; strtod's clamped value tells which.
  if (std::abs(std::strtod(digits.c_str(), nullptr)) < 1.0)
    return shown + " is below the smallest normal double (about 2.2e-308): it would be read as "
                   "0 or lose digits";
  return shown + " is beyond the largest double (about 1.8e308)";
}

} // namespace formflow::io
