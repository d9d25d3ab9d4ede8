// SPDX-License-Identifier: MIT
// A Python value written as the TOML literal a `--set key=value` would carry.
#pragma once

#include "formflow/io/case.hpp"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace formflow::python {

/// `value` as TOML text that the case loader parses back to the same value:
/// bool → true/false, int → its digits, float → Python's repr (the shortest text
/// that reads back to the same double, so a value set from Python and the same
/// number on the command line are one double), str → a quoted basic string,
/// list/tuple → an array, dict → an inline table. Throws TypeError naming `key`
/// for anything else (None, objects). Nothing is validated here: the loader does that.
std::string toml_literal(const std::string& key, pybind11::handle value);
/// The same at nesting `depth` (0 for the key's own value); deeper than a case value can
/// be, or a value that contains itself, throws InputError naming `key`.
std::string toml_literal_at(const std::string& key, pybind11::handle value, int depth);

/// The entries of a case dict as --set overrides, in the dict's order: dotted
/// keys ("friction.mu": 0.1) as they are; a nested table under a name without a
/// dot ({"friction": {"mu": 0.1}}) becomes one override per entry, so an
/// unknown section is reported as the unknown key it holds, like in a case file.
std::vector<io::Override> dict_overrides(const pybind11::dict& entries);

} // namespace formflow::python
