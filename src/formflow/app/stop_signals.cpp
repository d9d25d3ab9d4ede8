// SPDX-License-Identifier: MIT
// The signal handler and the flag it sets.
#include "formflow/app/stop_signals.hpp"

#include <signal.h>
#include <unistd.h>

#include <csignal>

namespace formflow::app {

namespace {

// The only state a handler may touch: volatile sig_atomic_t (C++ [support.signal]).
volatile std::sig_atomic_t received_signal = 0;

extern "C" void record_stop_signal(int signal) {
  if (received_signal != 0) ::_exit(signal_exit_code(signal)); // asked twice: stop now
  received_signal = signal;
}

} // namespace

void install_stop_handlers() {
  struct sigaction action = {};
  action.sa_handler = record_stop_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: a read or write under way when the signal comes resumes instead
  // of failing with EINTR in a library that does not retry.
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
  struct sigaction ignore = {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  ::sigaction(SIGXFSZ, &ignore, nullptr);
}

int stop_signal() {
  return received_signal;
}

StopRequested signal_stop_request() {
  return [] { return received_signal != 0; };
}

void throw_if_signalled() {
  if (received_signal != 0) throw Stopped("stopped by a signal during the solve");
}

int signal_exit_code(int signal) {
  return 128 + signal;
}

} // namespace formflow::app
