// SPDX-License-Identifier: MIT
// Reading an MSH file's numbers as Gmsh does, for the data check (mesh/msh_data.cpp): ASCII
// tokens or raw binary values in the file's byte order, each with where it starts.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

namespace formflow::mesh::msh_scan {

/// Thrown inside the scan with the whole message; msh_data_problem returns it.
struct Refusal {
  std::string text;
};

/// Where a number starts, to name it in a refusal.
struct Position {
  std::size_t at = 0;
  std::size_t line = 1;
};

/// Reads an MSH file's numbers as Gmsh does: ASCII numbers as whitespace-separated
/// tokens, binary ones as raw ints (4 bytes), sizes (8) and doubles (8) in the file's
/// byte order; section names and the 2.2 counts as text lines in both.
class Scanner {
public:
  Scanner(std::string_view bytes, bool binary, std::string_view path)
      : bytes_(bytes), binary_(binary), path_(path) {}

  bool binary() const { return binary_; }
  void set_swapped(bool swapped) { swapped_ = swapped; }
  bool at_end() const { return at_ >= bytes_.size(); }
  Position position() const { return {at_, line_}; }
  /// Where the next number starts (in ASCII past the blanks before it).
  Position next() {
    if (!binary_) skip_blank();
    return position();
  }
  std::size_t left() const { return bytes_.size() - at_; }

  [[noreturn]] void refuse_at(Position where, const std::string& what) const {
    throw Refusal{binary_ ? fmt::format("{}: byte {}: {}", path_, where.at, what)
                          : fmt::format("{}:{}: {}", path_, where.line, what)};
  }
  [[noreturn]] void refuse(const std::string& what) const { refuse_at(position(), what); }

  /// The bytes up to the next newline ("\r" dropped); refused at the file's end.
  std::string_view text_line() {
    const std::size_t end = bytes_.find('\n', at_);
    if (end == std::string_view::npos) refuse("the file ends inside a line");
    std::string_view line = bytes_.substr(at_, end - at_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at_ = end + 1;
    ++line_;
    return line;
  }

  /// Skips spaces, tabs and line ends (between ASCII numbers, and after binary data).
  void skip_blank() {
    while (at_ < bytes_.size() && is_blank(bytes_[at_])) {
      if (bytes_[at_] == '\n') ++line_;
      ++at_;
    }
  }

  /// Bytes one number of each kind takes at least: in ASCII a digit and a separator.
  std::size_t int_bytes() const { return binary_ ? 4 : 2; }
  std::size_t size_bytes() const { return binary_ ? 8 : 2; }
  std::size_t real_bytes() const { return binary_ ? 8 : 2; }

  std::int64_t integer(std::string_view what) {
    if (!binary_) return text_integer(token(what), what);
    std::int32_t value = 0;
    raw(&value, sizeof value, what);
    return value;
  }

  /// A size_t of a 4.1 file, as a signed number: above 2^63 it is refused as a count
  /// and as a tag alike.
  std::int64_t size(std::string_view what) {
    if (!binary_) return text_integer(token(what), what);
    std::uint64_t value = 0;
    raw(&value, sizeof value, what);
    if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
      refuse(fmt::format("{} {} ({} as a signed number) is above {}", what, value,
                         static_cast<std::int64_t>(value), max_msh_tag));
    return static_cast<std::int64_t>(value);
  }

  double real(std::string_view what) {
    if (binary_) {
      double value = 0;
      raw(&value, sizeof value, what);
      return value;
    }
    const std::string_view text = token(what);
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range) {
      // ±HUGE_VAL (∞) or a subnormal, which the coordinate check names; never a silent 0.
      const double clamped = std::strtod(std::string(text).c_str(), nullptr);
      if (clamped == 0) refuse(fmt::format("{} underflows to 0", what));
      return clamped;
    }
    if (error != std::errc() || end != text.data() + text.size())
      refuse(fmt::format("{} is not a number", what));
    return value;
  }

  /// A whole text line holding one integer (the 2.2 counts).
  std::int64_t line_integer(std::string_view what) {
    const Position start = position();
    std::string_view line = text_line();
    while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
    while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
    try {
      return text_integer(line, what);
    } catch (const Refusal&) {
      refuse_at(start, fmt::format("{} is not an integer on a line of its own", what));
    }
  }

  /// Refuses `count` entries of at least `bytes_each` bytes that the rest of the file
  /// cannot hold — before anything is read or reserved by the count.
  void hold(std::int64_t count, std::size_t bytes_each, std::string_view what) const {
    hold_at(position(), count, bytes_each, what);
  }
  /// As hold, naming `where` (the count's own place).
  void hold_at(Position where, std::int64_t count, std::size_t bytes_each,
               std::string_view what) const {
    if (count < 0) refuse_at(where, fmt::format("{}: a count of {} is negative", what, count));
    const std::uint64_t most = left() / bytes_each;
    if (static_cast<std::uint64_t>(count) > most)
      refuse_at(where,
                fmt::format("{} {} declared, but the {} bytes left in the file hold at most {} "
                            "(each takes at least {} bytes)",
                            count, what, left(), most, bytes_each));
  }

private:
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

  std::string_view token(std::string_view what) {
    skip_blank();
    const std::size_t begin = at_;
    while (at_ < bytes_.size() && !is_blank(bytes_[at_])) ++at_;
    if (at_ == begin) refuse(fmt::format("the file ends before {}", what));
    return bytes_.substr(begin, at_ - begin);
  }

  std::int64_t text_integer(std::string_view text, std::string_view what) const {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range)
      refuse(fmt::format("{} is an integer beyond ±2^63", what));
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
      refuse(fmt::format("{} is not an integer", what));
    return value;
  }

  void raw(void* value, std::size_t size, std::string_view what) {
    if (left() < size) refuse(fmt::format("the file ends before {}", what));
    std::memcpy(value, bytes_.data() + at_, size);
    if (swapped_) std::reverse(static_cast<char*>(value), static_cast<char*>(value) + size);
    at_ += size;
  }

  std::string_view bytes_;
  bool binary_;
  std::string_view path_;
  bool swapped_ = false;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
};

} // namespace formflow::mesh::msh_scan
