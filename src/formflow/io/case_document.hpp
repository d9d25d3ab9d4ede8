// SPDX-License-Identifier: MIT
// The TOML text of a case file or a --set value, bounded and parsed (toml11 v3).
#pragma once

#include <toml.hpp>

#include <string>

namespace formflow::io {

/// Reads `path` and parses it as TOML, after check_case_text has bounded its
/// size, line length, UTF-8 and nesting. Throws InputError (key "case file"
/// or "syntax") naming the path and, where known, the line.
toml::value read_case_document(const std::string& path);

/// Parses `text` (the content of a case file) as TOML, bounded by
/// check_case_text first; `source` names it in errors (a path). Throws InputError.
toml::value parse_case_document(const std::string& text, const std::string& source);

/// The `--set key=text` value as a TOML value; text that is not a TOML value
/// is a bare-word string. The text is bounded like a case file's; a violation
/// is an InputError("--set", 0, key, ...).
toml::value parse_override_value(const std::string& key, const std::string& text);

} // namespace formflow::io
