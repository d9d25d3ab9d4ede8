// SPDX-License-Identifier: MIT
// The formflow command line: run, check, case-reference, --version.
#pragma once

namespace formflow::app {

/// Exit codes: 0 ok · 1 internal error · 2 bad input or usage · 3 not converged.
enum ExitCode : int { Ok = 0, InternalFailure = 1, BadInput = 2, NotConverged = 3 };

/// Parses the arguments, runs the subcommand and returns the process exit code.
int run_cli(int argc, char** argv);

} // namespace formflow::app
