// SPDX-License-Identifier: MIT
// What every fuzz target shares: the input as text, and a scratch file per process.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace formflow::fuzz {

/// The fuzzer's bytes as a string (any bytes, NUL included).
inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// A file of this process under the temp directory, rewritten with `text`
/// for each input (load_case reads paths). Removed at exit.
class ScratchFile {
public:
  ScratchFile()
      : path_(std::filesystem::temp_directory_path() /
              ("formflow-fuzz-" + std::to_string(::getpid()) + ".toml")) {}
  ~ScratchFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  const std::string& write(const std::string& text) {
    std::ofstream(path_, std::ios::binary | std::ios::trunc) << text;
    name_ = path_.string();
    return name_;
  }

private:
  std::filesystem::path path_;
  std::string name_;
};

} // namespace formflow::fuzz
