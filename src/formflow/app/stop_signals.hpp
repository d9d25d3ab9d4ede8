// SPDX-License-Identifier: MIT
// SIGINT and SIGTERM as a request to stop at the next safe point, not a kill.
#pragma once

#include "formflow/core/stop_request.hpp"

namespace formflow::app {

/// Installs the handlers: the first SIGINT or SIGTERM only records its number
/// (async-signal-safe: one store to a sig_atomic_t); the solve and the writer
/// look at it at their safe points, undo their partial work and exit
/// 128 + signal. A second such signal ends the process at once (_exit), for
/// a user who will not wait for the current iteration to finish; a staging
/// directory may then stay behind, the previous results still intact.
/// Also ignores SIGXFSZ, so that a file-size limit fails the write (EFBIG,
/// reported, old results kept) instead of killing formflow half-way.
void install_stop_handlers();

/// The signal received (SIGINT, SIGTERM), or 0.
int stop_signal();

/// The StopRequested of this process: true once a signal was received.
StopRequested signal_stop_request();

/// Throws Stopped if a signal was received: called from the iteration callback.
void throw_if_signalled();

/// 130 for SIGINT, 143 for SIGTERM: the shell's 128 + signal convention.
int signal_exit_code(int signal);

} // namespace formflow::app
