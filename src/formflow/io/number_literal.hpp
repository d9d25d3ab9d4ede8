// SPDX-License-Identifier: MIT
// Whether a TOML number literal is exactly representable in range (toml11 clamps silently).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace formflow::io {

/// What is wrong with the TOML number `literal` (as written, underscores and
/// sign included) as a double (`integer` false) or a 64-bit integer (`integer`
/// true): "1e400 is beyond the largest double (about 1.8e308)", "1e-400 is
/// below the smallest normal double (about 2.2e-308): it would be read as 0 or
/// lose digits", "99999999999999999999 does not fit a 64-bit integer";
/// std::nullopt when it reads exactly as written (inf and nan are left to the
/// caller's finiteness check), or when it is not a number literal at all.
std::optional<std::string> number_literal_problem(std::string_view literal, bool integer);

} // namespace formflow::io
