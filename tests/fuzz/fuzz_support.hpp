// SPDX-License-Identifier: MIT
// What every fuzz target shares: the input as text.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace formflow::fuzz {

/// The fuzzer's bytes as a string (any bytes, NUL included).
inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

} // namespace formflow::fuzz
