// SPDX-License-Identifier: MIT
// Limits on the raw text of a case file (or a --set value), checked before toml11 parses it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace formflow::io {

/// Largest case file accepted, in bytes. A complete case with every key set is
/// about 3 KB and a 1000-point die profile under 20 KB. toml11 spends about
/// 2 µs per value, and a 64 KiB file holds at most 32 768 values: parsing the
/// worst file stays near 0.1 s (docs/reliability.md), where 1 MiB took 2–5 s.
inline constexpr std::size_t max_case_file_bytes = std::size_t{64} << 10;

/// Longest line accepted, in bytes. toml11 rescans a value's whole line for
/// comments once per value, so a file costs O(size × line length) on top of
/// its linear part: 1 KiB lines keep that below the linear part; longer lists
/// span several lines.
inline constexpr std::size_t max_case_line_bytes = 1024;

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
