// SPDX-License-Identifier: MIT
// toml11 values as case-key values: conversion, descriptions for messages, clamped numbers.
#include "formflow/io/toml_key_value.hpp"

#include "formflow/core/printable_text.hpp"
#include "formflow/io/number_literal.hpp"
#include "formflow/io/toml_lines.hpp"

#include <fmt/format.h>

namespace formflow::io {

std::string describe_toml_value(const toml::value& value) {
  switch (value.type()) {
  case toml::value_t::boolean: return value.as_boolean() ? "boolean true" : "boolean false";
  case toml::value_t::integer: return fmt::format("integer {}", value.as_integer());
  case toml::value_t::floating: return "real " + format_key_value(value.as_floating());
  case toml::value_t::string:
    return "string " + format_key_value(printable_text(value.as_string().str, 80));
  case toml::value_t::array: return "an array";
  case toml::value_t::table: return "a table";
  default: return "a date/time";
  }
}

std::string expected_type_text(const CaseKey& key) {
  switch (key.type) {
  case KeyType::Real: return "a real number";
  case KeyType::Integer: return "an integer";
  case KeyType::Enum: return "a string";
  case KeyType::StringList: return "a list of strings";
  case KeyType::PointList: return "a list of [x, y] pairs";
  case KeyType::Text: return "a string";
  case KeyType::NameMap: return "a table of strings";
  case KeyType::RealList: return "a number or a list of numbers";
  }
  return "?";
}

std::optional<KeyValue> convert_toml_value(const CaseKey& key, const toml::value& value) {
  switch (key.type) {
  case KeyType::Real:
    if (value.is_floating()) return KeyValue{value.as_floating()};
    if (value.is_integer()) return KeyValue{static_cast<Real>(value.as_integer())};
    return std::nullopt;
  case KeyType::Integer:
    if (value.is_integer()) return KeyValue{std::int64_t{value.as_integer()}};
    return std::nullopt;
  case KeyType::Enum:
    if (value.is_string()) return KeyValue{value.as_string().str};
    // A switch (choices "false", "true", e.g. thermal.enabled) takes a TOML boolean.
    if (value.is_boolean() && key.choices.size() == 2 && key.choices[0] == "false" &&
        key.choices[1] == "true")
      return KeyValue{std::string(value.as_boolean() ? "true" : "false")};
    return std::nullopt;
  case KeyType::StringList: {
    if (!value.is_array()) return std::nullopt;
    std::vector<std::string> list;
    for (const toml::value& entry : value.as_array()) {
      if (!entry.is_string()) return std::nullopt;
      list.push_back(entry.as_string().str);
    }
    return KeyValue{std::move(list)};
  }
  case KeyType::PointList: {
    if (!value.is_array()) return std::nullopt;
    KeyPoints points;
    for (const toml::value& entry : value.as_array()) {
      if (!entry.is_array() || entry.as_array().size() != 2) return std::nullopt;
      std::array<Real, 2> point{};
      for (std::size_t k = 0; k < 2; ++k) {
        const toml::value& number = entry.as_array()[k];
        if (number.is_floating())
          point[k] = number.as_floating();
        else if (number.is_integer())
          point[k] = static_cast<Real>(number.as_integer());
        else
          return std::nullopt;
      }
      points.push_back(point);
    }
    return KeyValue{std::move(points)};
  }
  case KeyType::Text:
    if (value.is_string()) return KeyValue{value.as_string().str};
    return std::nullopt;
  case KeyType::RealList: {
    const auto number = [](const toml::value& entry) -> std::optional<Real> {
      if (entry.is_floating()) return entry.as_floating();
      if (entry.is_integer()) return static_cast<Real>(entry.as_integer());
      return std::nullopt;
    };
    if (const auto single = number(value)) return KeyValue{std::vector<Real>{*single}};
    if (!value.is_array() || value.as_array().empty()) return std::nullopt;
    std::vector<Real> list;
    for (const toml::value& entry : value.as_array()) {
      const auto read = number(entry);
      if (!read) return std::nullopt;
      list.push_back(*read);
    }
    return KeyValue{std::move(list)};
  }
  case KeyType::NameMap: {
    if (!value.is_table()) return std::nullopt;
    NameMap map;
    for (const auto& [entry, text] : value.as_table()) {
      if (!text.is_string()) return std::nullopt;
      map[entry] = text.as_string().str;
    }
    return std::optional<KeyValue>(std::in_place, std::in_place_type<NameMap>, std::move(map));
  }
  }
  return std::nullopt;
}

std::optional<std::string> clamped_number(const toml::value& value) {
  if (value.is_floating() || value.is_integer())
    return number_literal_problem(source_text(value), value.is_integer());
  if (value.is_array())
    for (const toml::value& entry : value.as_array())
      if (auto problem = clamped_number(entry)) return problem;
  return std::nullopt;
}

} // namespace formflow::io
