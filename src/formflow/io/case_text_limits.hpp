// SPDX-License-Identifier: MIT
// Limits on the raw text of a case file (or a --set value), checked before toml11 parses it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace formflow::io {

/// Largest case file accepted, in bytes. A complete case with every key set is
/// about 3 KB and a 1000-point die profile about 30 KB; 1 MiB leaves room for
/// comments while bounding toml11's work on hostile input.
inline constexpr std::size_t max_case_file_bytes = std::size_t{1} << 20;

/// Longest line accepted, in bytes. toml11 rescans a value's whole line for
/// comments once per value, so a line costs O(values × length) ≤ O(length²):
/// 4 KiB bounds that at a few milliseconds; longer lists span several lines.
inline constexpr std::size_t max_case_line_bytes = 4096;

/// Deepest nesting accepted: arrays, inline tables and dotted-key parts
/// together. The deepest valid key, a die profile point, is 3 levels deep;
/// toml11 recurses once per level and overflows the stack near 10 000.
inline constexpr int max_case_nesting = 32;

/// Throws InputError(file, line, "syntax", ...) when `text` is longer than
/// max_case_file_bytes, has a line longer than max_case_line_bytes, is not
/// valid UTF-8 ("invalid UTF-8 at line N") or nests deeper than
/// max_case_nesting outside strings and comments. `file` names the source in
/// the message (a path or "--set").
void check_case_text(std::string_view text, const std::string& file);

} // namespace formflow::io
