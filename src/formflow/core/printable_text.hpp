// SPDX-License-Identifier: MIT
// User text made safe to echo in a message: no control bytes, no invalid UTF-8, bounded length.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace formflow {

/// Length of the valid UTF-8 sequence starting at `text[0]` (1–4), or 0 when
/// the bytes there are not valid UTF-8 (overlong forms, surrogates and code
/// points above U+10FFFF are invalid). `text` must not be empty.
std::size_t utf8_sequence_length(std::string_view text);

/// `text` fit to be echoed in a message: control bytes (but not tab) and
/// invalid UTF-8 bytes become \xNN; if the result would exceed `max_bytes`, it
/// is cut at a character boundary and ends with "…". Valid UTF-8 passes unchanged.
std::string printable_text(std::string_view text, std::size_t max_bytes = 200);

/// `text` without leading and trailing blanks (space, tab, CR, LF).
std::string trimmed(std::string_view text);

} // namespace formflow
