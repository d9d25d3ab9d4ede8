// SPDX-License-Identifier: MIT
// toml11 values as case-key values: conversion, descriptions for messages, clamped numbers.
#pragma once

#include "formflow/io/case_keys.hpp"

#include <toml.hpp>

#include <optional>
#include <string>

namespace formflow::io {

/// What `value` is, for "got ..." in messages: "integer 3", "string \"fine\"" (a
/// string's echo escaped and cut), "an array".
std::string describe_toml_value(const toml::value& value);

/// What `key` expects, for "expected ..." in messages: "a real number", "a list of [x, y] pairs".
std::string expected_type_text(const CaseKey& key);

/// `value` as `key`'s type (integers are accepted for real keys); std::nullopt
/// when its TOML type does not fit. Ranges and choices are not checked here.
std::optional<KeyValue> convert_toml_value(const CaseKey& key, const toml::value& value);

/// A number in `value` (or in its arrays) that toml11 clamped or rounded to 0
/// while reading (number_literal_problem); std::nullopt when every number reads
/// as written.
std::optional<std::string> clamped_number(const toml::value& value);

} // namespace formflow::io
