// SPDX-License-Identifier: MIT
// Error types: user input errors (exit 2) and internal assertions (bugs).
#pragma once

#include <stdexcept>
#include <string>

namespace formflow {

/// A problem with the user's input: which file, line and key, what is wrong,
/// and what would be valid. Printed as `file:line: key: message (hint)`.
struct InputError : std::runtime_error {
  std::string file;    ///< case file path, or "--set" / "<default>"
  int line = 0;        ///< 1-based line in `file`, 0 when unknown
  std::string key;     ///< dotted key, e.g. "friction.mu"
  std::string message; ///< what is wrong
  std::string hint;    ///< what would be valid

  InputError(std::string file_, int line_, std::string key_, std::string message_,
             std::string hint_ = {});
};

/// An internal inconsistency (a bug in formflow, never the user's fault).
struct InternalError : std::logic_error {
  using std::logic_error::logic_error;
};

[[noreturn]] void fail_assertion(const char* condition, const char* file, int line,
                                 const std::string& message);

} // namespace formflow

#if !defined(NDEBUG) || defined(FORMFLOW_ENABLE_ASSERTS)
#define FF_ASSERT(cond, msg)                                                                       \
  do {                                                                                             \
    if (!(cond)) ::formflow::fail_assertion(#cond, __FILE__, __LINE__, (msg));                     \
  } while (false)
#else
#define FF_ASSERT(cond, msg)                                                                       \
  do {                                                                                             \
  } while (false)
#endif
