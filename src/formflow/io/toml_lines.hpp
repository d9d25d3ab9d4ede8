// SPDX-License-Identifier: MIT
// Line and column of toml11 values in O(log n) each, from one index of the source's newlines.
#pragma once

#include <toml.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace formflow::io {

/// Where a value starts in its source: 1-based line and column (in bytes).
struct TomlPosition {
  std::size_t line = 0;
  std::size_t column = 0;
  auto operator<=>(const TomlPosition&) const = default;
};

/// toml11 v3's `value.location().line()` counts the newlines from the start of
/// the file on every call (and copies the value's whole line), so sorting n
/// keys by position costs O(n log n × file size). This index finds the
/// newlines once per source and answers each position by binary search.
class TomlLines {
public:
  /// Position of `value`'s first byte; {0, 0} for a value with no source (a
  /// value built in code).
  TomlPosition position(const toml::value& value);

private:
  std::shared_ptr<const std::vector<char>> source_; ///< the source indexed, kept alive
  std::vector<std::size_t> line_starts_;            ///< offset of each line's first byte
};

/// The line `value` starts on (0 for a value with no source).
int line_of(TomlLines& lines, const toml::value& value);

/// The entries of `table` in the order they appear in the file: each position is
/// found once (O(log n)), then the entries are sorted by it.
std::vector<std::pair<std::string, const toml::value*>> in_file_order(const toml::value& table,
                                                                      TomlLines& lines);

} // namespace formflow::io

namespace formflow::io {

/// The bytes of `value` as written in its source (`1e400`, `0x_ff`); empty for
/// a value with no source. toml11 reads numbers through std::istream, which
/// clamps out-of-range literals silently: this text lets the caller re-read them.
std::string source_text(const toml::value& value);

} // namespace formflow::io
