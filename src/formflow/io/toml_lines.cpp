// SPDX-License-Identifier: MIT
// Positions of toml11 values from their byte offset and a sorted table of line starts.
#include "formflow/io/toml_lines.hpp"

#include <algorithm>

namespace formflow::io {

TomlPosition TomlLines::position(const toml::value& value) {
  // toml11 keeps the parsed bytes and each value's first byte in its region
  // (toml/region.hpp); the detail interface is the only way to the offset.
  const auto* region = dynamic_cast<const toml::detail::region*>(toml::detail::get_region(value));
  if (!region || !region->source()) {
    const toml::source_location where = value.location(); // not from a parsed file: no cost
    return {where.line(), where.column()};
  }
  if (region->source() != source_) {
    source_ = region->source();
    line_starts_.assign(1, 0);
    for (std::size_t k = 0; k < source_->size(); ++k)
      if ((*source_)[k] == '\n') line_starts_.push_back(k + 1);
  }
  const auto offset = static_cast<std::size_t>(region->first() - source_->cbegin());
  const auto next_line = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<std::size_t>(next_line - line_starts_.begin());
  return {line, offset - line_starts_[line - 1] + 1};
}

int line_of(TomlLines& lines, const toml::value& value) {
  return static_cast<int>(lines.position(value).line);
}

std::vector<std::pair<std::string, const toml::value*>> in_file_order(const toml::value& table,
                                                                      TomlLines& lines) {
  std::vector<std::pair<TomlPosition, std::pair<std::string, const toml::value*>>> placed;
  for (const auto& [name, value] : table.as_table())
    placed.push_back({lines.position(value), {name, &value}});
  std::sort(placed.begin(), placed.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<std::string, const toml::value*>> entries;
  for (auto& [position, entry] : placed) entries.push_back(std::move(entry));
  return entries;
}

} // namespace formflow::io

namespace formflow::io {

std::string source_text(const toml::value& value) {
  const auto* region = toml::detail::get_region(value);
  return region && region->is_ok() ? region->str() : std::string();
}

} // namespace formflow::io
