// SPDX-License-Identifier: MIT
// Formatting of input errors and assertion failures.
#include "formflow/core/error.hpp"

#include "formflow/core/printable_text.hpp"

#include <fmt/format.h>

namespace formflow {

namespace {
// Every field may echo what the user typed (a 100 KB key, raw bytes): each is
// escaped and bounded so that a message stays one readable line.
std::string render(const std::string& file, int line, const std::string& key,
                   const std::string& message, const std::string& hint) {
  const std::string path = printable_text(file, 400);
  std::string where = line > 0 ? fmt::format("{}:{}", path, line) : path;
  std::string text =
      fmt::format("{}: {}: {}", where, printable_text(key, 100), printable_text(message, 600));
  if (!hint.empty()) text += fmt::format(" ({})", printable_text(hint, 600));
  return text;
}
} // namespace

InputError::InputError(std::string file_, int line_, std::string key_, std::string message_,
                       std::string hint_)
    : std::runtime_error(render(file_, line_, key_, message_, hint_)), file(std::move(file_)),
      line(line_), key(std::move(key_)), message(std::move(message_)), hint(std::move(hint_)) {}

void fail_assertion(const char* condition, const char* file, int line, const std::string& message) {
  throw InternalError(
      fmt::format("{}:{}: assertion `{}` failed: {}", file, line, condition, message));
}

} // namespace formflow
