// SPDX-License-Identifier: MIT
// Asking a long operation to stop at its next safe point (after SIGINT/SIGTERM).
#pragma once

#include <functional>
#include <stdexcept>

namespace formflow {

/// Asked at the safe points of a long operation (between iterations, between
/// result files); true means "stop now". Empty: never stop.
using StopRequested = std::function<bool()>;

/// Thrown at a safe point once a stop was requested. Whoever throws it has
/// already undone its partial work (temporary files removed, older results
/// left as they were); app/ turns it into exit 130/143.
struct Stopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// True when `stop_requested` is set and answers true.
inline bool is_stop_requested(const StopRequested& stop_requested) {
  return stop_requested && stop_requested();
}

} // namespace formflow
