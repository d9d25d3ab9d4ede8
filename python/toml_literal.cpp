// SPDX-License-Identifier: MIT
// Python values → TOML literals, and case dicts → the overrides the loader validates.
#include "toml_literal.hpp"

#include "formflow/core/error.hpp"

#include <fmt/format.h>

#include <iterator>

namespace formflow::python {

namespace py = pybind11;

namespace {

/// A TOML basic string: quotes and backslashes escaped, control characters as \uXXXX.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char character : text) {
    const auto byte = static_cast<unsigned char>(character);
    if (character == '"' || character == '\\') {
      out += '\\';
      out += character;
    } else if (byte < 0x20 || byte == 0x7f) {
      fmt::format_to(std::back_inserter(out), "\\u{:04X}", byte);
    } else {
      out += character;
    }
  }
  return out + "\"";
}

/// The deepest case value is a list of [x, y] points: two levels. Eight leave room and
/// keep the recursion far from the stack's end (a 10⁵-deep or self-referencing list
/// overflowed it: a segfault).
constexpr int max_value_depth = 8;

std::string key_name(const std::string& key, py::handle name) {
  if (!py::isinstance<py::str>(name))
    throw py::type_error(fmt::format("{}: a case table's keys are strings, got {}", key,
                                     py::repr(name).cast<std::string>()));
  return name.cast<std::string>();
}

} // namespace

std::string toml_literal(const std::string& key, py::handle value) {
  return toml_literal_at(key, value, 0);
}

std::string toml_literal_at(const std::string& key, py::handle value, int depth) {
  if (depth > max_value_depth)
    throw InputError("case", 0, key,
                     fmt::format("the value nests lists or dicts more than {} deep (or contains "
                                 "itself)",
                                 max_value_depth),
                     "a case value is a number, a string, a list of them or of [x, y] pairs, "
                     "or a table of strings");
  // bool before int: Python's True is an int too.
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(value)) return quoted(value.cast<std::string>());
  if (PyLong_Check(value.ptr()) || (PyIndex_Check(value.ptr()) && !PyFloat_Check(value.ptr())))
    return py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  if (PyFloat_Check(value.ptr()) || PyNumber_Check(value.ptr())) {
    // float.__repr__ of the value as a Python float: numpy scalars print otherwise.
    const py::float_ number(py::reinterpret_borrow<py::object>(value));
    return py::repr(number).cast<std::string>();
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string out = "[";
    for (const py::handle entry : value) {
      if (out.size() > 1) out += ", ";
      out += toml_literal_at(key, entry, depth + 1);
    }
    return out + "]";
  }
  if (py::isinstance<py::dict>(value)) {
    std::string out = "{";
    for (const auto& [name, entry] : value.cast<py::dict>()) {
      if (out.size() > 1) out += ",";
      out += " " + quoted(key_name(key, name)) + " = " + toml_literal_at(key, entry, depth + 1);
    }
    return out + " }";
  }
  throw py::type_error(fmt::format("{}: {} is not a case value (use a number, a string, a list "
                                   "or a dict)",
                                   key, py::repr(value).cast<std::string>()));
}

std::vector<io::Override> dict_overrides(const py::dict& entries) {
  std::vector<io::Override> overrides;
  for (const auto& [name_object, value] : entries) {
    const std::string name = key_name("case", name_object);
    if (py::isinstance<py::dict>(value) && name.find('.') == std::string::npos) {
      for (const auto& [leaf, entry] : value.cast<py::dict>()) {
        const std::string key = name + "." + key_name(name, leaf);
        overrides.emplace_back(key, toml_literal(key, entry));
      }
      continue;
    }
    overrides.emplace_back(name, toml_literal(name, value));
  }
  return overrides;
}

} // namespace formflow::python
