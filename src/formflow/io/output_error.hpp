// SPDX-License-Identifier: MIT
// The error of a result set that could not be written (full disk, I/O error).
#pragma once

#include <stdexcept>

namespace formflow::io {

/// Writing results failed for a reason outside formflow (no space left, an
/// I/O error, a directory appearing where a file goes). Thrown only after the
/// output directory was put back as it was; the message names the file and
/// the reason. app/ prints it and exits 1.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

} // namespace formflow::io
