// SPDX-License-Identifier: MIT
// Reading case-file text within its limits and turning toml11's errors into InputErrors.
#include "formflow/io/case_document.hpp"

#include "formflow/core/error.hpp"
#include "formflow/core/printable_text.hpp"
#include "formflow/io/case_text_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace formflow::io {

namespace {

/// One-line message and hint from toml11's multi-line, underlined syntax error.
InputError syntax_error(const std::string& path, const toml::syntax_error& error) {
  std::istringstream lines(error.what());
  std::string line, summary, annotation;
  std::getline(lines, summary);
  for (const std::string prefix : {"[error] ", "toml::"})
    if (summary.rfind(prefix, 0) == 0) summary.erase(0, prefix.size());
  if (const auto colon = summary.find(": ");
      colon != std::string::npos && summary.find(' ') > colon)
    summary.erase(0, colon + 2); // toml::parse_table: → drop the parser function name
  while (std::getline(lines, line)) {
    const auto bar = line.find(" | ");
    if (bar == std::string::npos) continue;
    const auto mark = line.find_first_not_of(' ', bar + 3);
    if (mark == std::string::npos || (line[mark] != '^' && line[mark] != '~')) continue;
    const auto text = line.find_first_not_of("^~- ", mark);
    if (text != std::string::npos) annotation = line.substr(text);
  }
  std::string message = "invalid TOML: " + summary;
  if (!annotation.empty() && annotation != "here") message += ": " + annotation;
  std::string hint = "in `" + printable_text(trimmed(error.location().line_str()), 120) + "`";
  if (summary.find("unknown value") != std::string::npos) hint += "; strings need quotes";
  return InputError(path, static_cast<int>(error.location().line()), "syntax", message, hint);
}

/// The whole file, refusing (before reading it) one larger than a case file can be.
std::string read_bounded(const std::string& path) {
  const std::string key = "case file";
  // std::filesystem and the C library would read the path up to its NUL: another file.
  if (path.find('\0') != std::string::npos)
    throw InputError(path, 0, key, "the path contains a NUL byte", "a path without NUL");
  std::error_code code;
  if (!std::filesystem::exists(path, code))
    throw InputError(path, 0, key, "no such file",
                     "check the path; without a case file the paper's benchmark is run");
  if (!std::filesystem::is_regular_file(path, code))
    throw InputError(path, 0, key, "not a regular file", "give the path of a .toml file");
  const auto size = std::filesystem::file_size(path, code);
  if (!code && size > max_case_file_bytes)
    throw InputError(
        path, 0, key,
        fmt::format("{} bytes, more than the limit of {} bytes", size, max_case_file_bytes),
        "a complete case is a few kilobytes: is this the right file?");
  std::ifstream stream(path, std::ios::binary);
  if (!stream)
    throw InputError(path, 0, key, "cannot be opened for reading", "check its permissions");
  // One byte past the size found (at most past the limit), so a file that grew
  // since file_size is still refused.
  const std::size_t expected = code ? max_case_file_bytes : static_cast<std::size_t>(size);
  std::string text(std::min(expected, max_case_file_bytes) + 1, '\0');
  stream.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(stream.gcount()));
  if (text.size() > expected && text.size() <= max_case_file_bytes)
    throw InputError(path, 0, key, "changed while it was being read", "read it again");
  return text;
}

toml::value parse_text(const std::string& text, const std::string& source) {
  std::istringstream stream(text);
  return toml::parse(stream, source);
}

} // namespace

toml::value read_case_document(const std::string& path) {
  return parse_case_document(read_bounded(path), path);
}

toml::value parse_case_document(const std::string& text, const std::string& path) {
  check_case_text(text, path);
  try {
    return parse_text(text, path);
  } catch (const toml::syntax_error& error) {
    throw syntax_error(path, error);
  } catch (const toml::exception& error) {
    throw InputError(path, static_cast<int>(error.location().line()), "syntax",
                     "invalid TOML: " + printable_text(trimmed(error.what()), 300), "");
  }
}

toml::value parse_override_value(const std::string& key, const std::string& text) {
  const std::string document = "value = " + text + "\n";
  try {
    check_case_text(document, "--set");
  } catch (const InputError& error) {
    throw InputError("--set", 0, key, error.message, error.hint);
  }
  try {
    const toml::value parsed = parse_text(document, "--set");
    if (parsed.as_table().size() == 1 && parsed.contains("value")) return parsed.at("value");
  } catch (const toml::exception&) {
    // not TOML: a bare word
  }
  return toml::value(trimmed(text));
}

} // namespace formflow::io
