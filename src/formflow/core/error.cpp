// SPDX-License-Identifier: MIT
// Formatting of input errors and assertion failures.
#include "formflow/core/error.hpp"

#include <fmt/format.h>

namespace formflow {

namespace {
std::string render(const std::string& file, int line, const std::string& key,
                   const std::string& message, const std::string& hint) {
  std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  std::string text = fmt::format("{}: {}: {}", where, key, message);
  if (!hint.empty()) text += fmt::format(" ({})", hint);
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
