// SPDX-License-Identifier: MIT
// One linear pass over a case file's bytes: size, line length, UTF-8 and nesting depth.
#include "formflow/io/case_text_limits.hpp"

#include "formflow/core/error.hpp"
#include "formflow/core/printable_text.hpp"

#include <fmt/format.h>

#include <vector>

namespace formflow::io {

namespace {

/// Tracks the nesting that toml11 recurses on: open arrays and inline tables,
/// plus the parts of the dotted key being read (`a.b.c = 1` nests 3 tables).
/// Strings and comments are skipped, so brackets and dots inside them do not count.
class NestingScanner {
public:
  NestingScanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  void run() {
    start_line();
    while (at_ < text_.size()) step();
  }

private:
  void step() {
    const char c = text_[at_];
    if (c == '\n') {
      ++line_;
      ++at_;
      if (open_.empty()) start_line();
      return;
    }
    if (c == '#') return skip_comment();
    if (c == '"' || c == '\'') return skip_string(c);
    if (c == ' ' || c == '\t' || c == '\r') return void(++at_);
    const bool line_start = at_line_start_;
    at_line_start_ = false;
    ++at_;
    switch (c) {
    case '[':
      if (line_start && open_.empty()) { // [table] or [[array.of.tables]]: a key path follows
        in_key_ = true;
        key_parts_ = 1;
      }
      return open('[');
    case '{':
      open('{');
      in_key_ = true; // an inline table starts with a key
      key_parts_ = 1;
      return;
    case ']':
    case '}':
      if (!open_.empty()) open_.pop_back();
      in_key_ = false;
      return;
    case ',':
      if (!open_.empty() && open_.back() == '{') in_key_ = true, key_parts_ = 1;
      return;
    case '=': in_key_ = false; return;
    case '.':
      if (in_key_) ++key_parts_, check_depth();
      return;
    default: return;
    }
  }

  void start_line() {
    at_line_start_ = true;
    in_key_ = true;
    key_parts_ = 1;
  }

  void open(char bracket) {
    open_.push_back(bracket);
    check_depth();
  }

  void check_depth() const {
    const auto depth = static_cast<int>(open_.size()) + (in_key_ ? key_parts_ : 0);
    if (depth <= max_case_nesting) return;
    throw InputError(file_, line_, "syntax",
                     fmt::format("nesting deeper than {} levels (arrays, inline tables and "
                                 "dotted-key parts together)",
                                 max_case_nesting),
                     "no case key nests deeper than 3 levels: a die profile point "
                     "geometry.die_profile = [[x, y], ...]");
  }

  void skip_comment() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }

  /// Skips a basic ("…", """…""") or literal ('…', '''…''') string; an
  /// unterminated one runs to its line's end (toml11 then reports it).
  void skip_string(char quote) {
    at_line_start_ = false;
    const bool multi_line = text_.substr(at_, 3) == std::string(3, quote);
    at_ += multi_line ? 3 : 1;
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\\' && quote == '"') {
        at_ += 2;
        continue;
      }
      if (c == '\n') {
        if (!multi_line) return; // toml11 reports the unterminated string
        ++line_;
      }
      if (c == quote && (!multi_line || text_.substr(at_, 3) == std::string(3, quote))) {
        at_ += multi_line ? 3 : 1;
        return;
      }
      ++at_;
    }
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t at_ = 0;
  int line_ = 1;
  std::vector<char> open_; ///< the unclosed '[' and '{', innermost last
  bool at_line_start_ = true;
  bool in_key_ = true;
  int key_parts_ = 1;
};

/// Line length and UTF-8, in one pass; throws at the first offending line.
void check_lines(std::string_view text, const std::string& file) {
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t at = 0; at < text.size();) {
    if (text[at] == '\n') {
      ++line;
      line_start = ++at;
      continue;
    }
    if (at - line_start >= max_case_line_bytes)
      throw InputError(file, line, "syntax",
                       fmt::format("line longer than {} bytes", max_case_line_bytes),
                       file == "--set" ? "put long lists in the case file, over several lines"
                                       : "break long lists over several lines: TOML arrays may "
                                         "span lines");
    const std::size_t length = utf8_sequence_length(text.substr(at));
    if (length == 0)
      throw InputError(file, line, "syntax",
                       fmt::format("invalid UTF-8 at line {} (byte 0x{:02X})", line,
                                   static_cast<unsigned char>(text[at])),
                       "TOML files are UTF-8 text: save the file as UTF-8");
    at += length;
  }
}

} // namespace

void check_case_text(std::string_view text, const std::string& file) {
  if (text.size() > max_case_file_bytes)
    throw InputError(
        file, 0, "case file",
        fmt::format("{} bytes, more than the limit of {} bytes", text.size(), max_case_file_bytes),
        "a complete case is a few kilobytes: is this the right file?");
  check_lines(text, file);
  NestingScanner(text, file).run();
}

} // namespace formflow::io
