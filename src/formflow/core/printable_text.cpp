// SPDX-License-Identifier: MIT
// Escaping and truncating user text for messages, and the UTF-8 decoding it needs.
#include "formflow/core/printable_text.hpp"

#include <fmt/format.h>

namespace formflow {

std::size_t utf8_sequence_length(std::string_view text) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(0);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  char32_t code = 0, smallest = 0;
  if ((lead & 0xE0) == 0xC0) {
    length = 2, code = lead & 0x1F, smallest = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3, code = lead & 0x0F, smallest = 0x800;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4, code = lead & 0x07, smallest = 0x10000;
  } else {
    return 0; // a continuation byte or 0xF8–0xFF cannot start a character
  }
  if (text.size() < length) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(k) & 0x3F);
  }
  const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
  if (code < smallest || surrogate || code > 0x10FFFF) return 0;
  return length;
}

std::string printable_text(std::string_view text, std::size_t max_bytes) {
  std::string result;
  const std::string_view ellipsis = "…";
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t length = utf8_sequence_length(text.substr(at));
    const auto byte = static_cast<unsigned char>(text[at]);
    const bool control = length == 1 && ((byte < 0x20 && byte != '\t') || byte == 0x7F);
    const std::string piece = length == 0 || control ? fmt::format("\\x{:02X}", byte)
                                                     : std::string(text.substr(at, length));
    if (result.size() + piece.size() > max_bytes) return result + std::string(ellipsis);
    result += piece;
    at += length == 0 ? 1 : length;
  }
  return result;
}

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return std::string(text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1));
}

} // namespace formflow
