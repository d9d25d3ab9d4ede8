// SPDX-License-Identifier: MIT
// Text renderings of the case-key table: values, valid ranges and the Markdown reference.
#include "formflow/io/case_keys.hpp"

#include <fmt/format.h>

namespace formflow::io {

namespace {

std::string format_real(Real value) {
  std::string text = fmt::format("{}", value);
  // Keep reals recognisable as TOML floats: 10 → 10.0 (inf/nan and 1e-06 are left alone).
  if (text.find_first_of(".eEni") == std::string::npos) text += ".0";
  return text;
}

std::string toml_quoted(std::string_view text) {
  std::string result = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') result += '\\';
    result += c;
  }
  return result + "\"";
}

std::string bound_text(const Bound& bound, bool lower) {
  const char* relation = lower ? (bound.inclusive ? "≥" : ">") : (bound.inclusive ? "≤" : "<");
  return fmt::format("{} {}", relation, *bound.value);
}

std::string choices_text(const CaseKey& key) {
  std::string text;
  for (std::string_view choice : key.choices)
    text += (text.empty() ? "" : ", ") + toml_quoted(choice);
  return text;
}

/// A Markdown table cell: pipes would end the cell.
std::string cell(std::string_view text) {
  std::string result;
  for (const char c : text) {
    if (c == '|') result += '\\';
    result += c;
  }
  return result;
}

std::string section_table(const CaseSection& section) {
  std::string text = fmt::format("## [{}]\n\n{}\n\n", section.name, section.doc);
  text += "| key | type | default | valid values | unit | description |\n";
  text += "|---|---|---|---|---|---|\n";
  for (const CaseKey& key : case_keys()) {
    if (key.section() != section.name) continue;
    text += fmt::format("| `{}` | {} | `{}` | {} | {} | {} |\n", key.leaf(),
                        key_type_name(key.type), cell(format_key_value(key.default_value)),
                        cell(valid_values_text(key)), cell(key.unit), cell(key.doc));
  }
  return text + "\n";
}

std::string default_case_file() {
  std::string text = "```toml\n";
  for (const CaseSection& section : case_sections()) {
    text += fmt::format("[{}]\n", section.name);
    for (const CaseKey& key : case_keys())
      if (key.section() == section.name)
        text += fmt::format("{} = {}\n", key.leaf(), format_key_value(key.default_value));
    text += section.name == case_sections().back().name ? "" : "\n";
  }
  return text + "```\n";
}

} // namespace

std::string format_key_value(const KeyValue& value) {
  if (const auto* real = std::get_if<Real>(&value)) return format_real(*real);
  if (const auto* integer = std::get_if<std::int64_t>(&value)) return fmt::format("{}", *integer);
  if (const auto* text = std::get_if<std::string>(&value)) return toml_quoted(*text);
  if (const auto* points = std::get_if<KeyPoints>(&value)) {
    std::string list = "[";
    for (const auto& point : *points)
      list += fmt::format("{}[{}, {}]", list.size() > 1 ? ", " : "", format_real(point[0]),
                          format_real(point[1]));
    return list + "]";
  }
  if (const auto* reals = std::get_if<std::vector<Real>>(&value)) {
    if (reals->size() == 1) return format_real(reals->front()); // one value for all
    std::string list = "[";
    for (const Real entry : *reals) list += (list.size() > 1 ? ", " : "") + format_real(entry);
    return list + "]";
  }
  if (const auto* map = std::get_if<NameMap>(&value)) {
    // A TOML inline table; keys quoted, so any physical name is valid.
    std::string table = "{";
    for (const auto& [entry, text] : *map)
      table += (table.size() > 1 ? ", " : "") + toml_quoted(entry) + " = " + toml_quoted(text);
    return table + "}";
  }
  std::string text = "[";
  for (const std::string& entry : std::get<std::vector<std::string>>(value))
    text += (text.size() > 1 ? ", " : "") + toml_quoted(entry);
  return text + "]";
}

std::string_view key_type_name(KeyType type) {
  switch (type) {
  case KeyType::Real: return "real";
  case KeyType::Integer: return "integer";
  case KeyType::Enum: return "string";
  case KeyType::StringList: return "list of strings";
  case KeyType::PointList: return "list of [x, y]";
  case KeyType::Text: return "string";
  case KeyType::NameMap: return "table of strings";
  case KeyType::RealList: return "real or list of reals";
  }
  return "?";
}

std::string valid_values_text(const CaseKey& key) {
  std::string text;
  switch (key.type) {
  case KeyType::Real:
  case KeyType::Integer:
  case KeyType::RealList:
    if (key.smallest_nonzero && key.upper.value)
      text = fmt::format("0, or {} ≤ value {} {}", *key.smallest_nonzero,
                         key.upper.inclusive ? "≤" : "<", *key.upper.value);
    else if (key.lower.value && key.upper.value)
      text = fmt::format("{} {} value {} {}", *key.lower.value, key.lower.inclusive ? "≤" : "<",
                         key.upper.inclusive ? "≤" : "<", *key.upper.value);
    else if (key.lower.value)
      text = bound_text(key.lower, true);
    else if (key.upper.value)
      text = bound_text(key.upper, false);
    else
      text = "any finite value";
    if (key.type == KeyType::RealList) text = "one number, or a list of numbers each " + text;
    break;
  case KeyType::Enum: text = "one of " + choices_text(key); break;
  case KeyType::StringList:
    text = "each of " + choices_text(key) + " at most once; may be empty";
    break;
  case KeyType::PointList: text = "finite [x, y] pairs"; break;
  case KeyType::Text: text = "a path"; break;
  case KeyType::NameMap: text = "entries `name = part`, part one of " + choices_text(key); break;
  }
  if (key.max_entries > 0) text += fmt::format(", at most {}", key.max_entries);
  if (!key.constraint.empty()) text += fmt::format("; {}", key.constraint);
  if (!key.range_reason.empty()) text += fmt::format(" (why: {})", key.range_reason);
  return text;
}

std::string case_reference_markdown() {
  std::string text =
      "# Case file reference\n\n"
      "<!-- Generated from src/formflow/io/keys/*_keys.cpp by\n"
      "     `build/formflow case-reference > docs/case-reference.md`; do not edit by hand. -->\n\n"
      "A case file is TOML with the sections below. Every key is optional and defaults to\n"
      "the paper's benchmark (SPEC §4); an unknown section or key is an error. Real-valued\n"
      "keys also accept integers (`size = 1`). Any key can be overridden on the command\n"
      "line after the file is read, in order: `--set section.key=value`, where the value is\n"
      "TOML and a bare word is taken as a string, e.g. `--set friction.mu=0.1`,\n"
      "`--set mesh.element=Q1`, `--set 'friction.on=[\"die\"]'`. Checks that involve two\n"
      "keys (mesh size against the lengths, exit against entry height, rate1 against\n"
      "rate2) run after all keys are set. `formflow check CASE` validates without solving.\n\n";
  for (const CaseSection& section : case_sections()) text += section_table(section);
  text += "## The default case\n\nEquivalent to running without a case file:\n\n";
  return text + default_case_file();
}

} // namespace formflow::io
