// SPDX-License-Identifier: MIT
// Die angles in the tests are written in degrees, as in the case files.
#pragma once

#include <numbers>

namespace formflow::testing {

/// One degree in radians: `15 * degree`.
inline constexpr double degree = std::numbers::pi / 180.0;

} // namespace formflow::testing
